/PROG  BENDING
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 100;
MEMORY_SIZE	= 0;
PROTECT		= READ_WRITE;
TCD:  STACK_SIZE	= 0,
      TASK_PRIORITY	= 50,
      TIME_SLICE	= 0,
      BUSY_LAMP_OFF	= 0,
      ABORT_REQUEST	= 0,
      PAUSE_REQUEST	= 0;
DEFAULT_GROUP	= 1,*,*,*,*;
CONTROL_CODE	= 00000000 00000000;
/MN
   1:  !note: renamed 'suction gripper' ;
   2:  !to 'suction_gripper': not a ;
   3:  !valid FANUC LS identifier ;
   4:  !note: TCP speed rounded to the ;
   5:  !controller's steps on 12 lines, ;
   6:  !the largest: program bending, ;
   7:  !move 16 (b6_bend): TCP speed ;
   8:  !370.588 mm/s written as 371 mm/s ;
   9:  !workbench program bending ;
  10:  !frames (set below from PR): ;
  11:  !UTOOL[1]: suction_gripper ;
  12:  !UT1 mass 2.500 kg ;
  13:  !UT1 cog 0.0,0.0,55.0 mm ;
  14:  !UFRAME[1]: base ;
  15:  PR[90]=LPOS-LPOS ;
  16:  PR[90,1]=0.000000 ;
  17:  PR[90,2]=0.000000 ;
  18:  PR[90,3]=120.000000 ;
  19:  PR[90,4]=0.000000 ;
  20:  PR[90,5]=0.000000 ;
  21:  PR[90,6]=0.000000 ;
  22:  UTOOL[1]=PR[90] ;
  23:  PR[90]=LPOS-LPOS ;
  24:  PR[90,1]=0.000000 ;
  25:  PR[90,2]=0.000000 ;
  26:  PR[90,3]=0.000000 ;
  27:  PR[90,4]=0.000000 ;
  28:  PR[90,5]=0.000000 ;
  29:  PR[90,6]=0.000000 ;
  30:  UFRAME[1]=PR[90] ;
  31:  !bending: 6 bends (front/elbow ;
  32:  !A/no flip) ;
  33:  !note: the project's io has no ;
  34:  !output 'bend start' and no input ;
  35:  !'bend done': the press handshake ;
  36:  !is comments only ;
  37:  !load: the plan has no blank ;
  38:  !station, the blank is put into ;
  39:  !the gripper here ;
  40:  !gripper close: the project has ;
  41:  !no io.gripper, add one ;
  42:  !bend 'b23' (step 1) ;
  43:  UTOOL_NUM=1 ;
  44:  UFRAME_NUM=1 ;
  45:J P[1] 100% FINE ;
  46:L P[2] 370mm/sec FINE ;
  47:  !press: pulse output 'bend start' ;
  48:  !(missing in io.outputs) ;
  49:  !press: wait for input 'bend ;
  50:  !done' (missing in io.inputs) ;
  51:L P[3] 370mm/sec FINE ;
  52:  !bend 'b45' (step 2) ;
  53:J P[4] 100% FINE ;
  54:L P[5] 370mm/sec FINE ;
  55:  !press: pulse output 'bend start' ;
  56:  !(missing in io.outputs) ;
  57:  !press: wait for input 'bend ;
  58:  !done' (missing in io.inputs) ;
  59:L P[6] 370mm/sec FINE ;
  60:  !bend 'b12' (step 3) ;
  61:J P[7] 100% FINE ;
  62:L P[8] 365mm/sec FINE ;
  63:  !press: pulse output 'bend start' ;
  64:  !(missing in io.outputs) ;
  65:  !press: wait for input 'bend ;
  66:  !done' (missing in io.inputs) ;
  67:L P[9] 365mm/sec FINE ;
  68:  !bend 'b14' (step 4) ;
  69:J P[10] 100% FINE ;
  70:L P[11] 365mm/sec FINE ;
  71:  !press: pulse output 'bend start' ;
  72:  !(missing in io.outputs) ;
  73:  !press: wait for input 'bend ;
  74:  !done' (missing in io.inputs) ;
  75:L P[12] 365mm/sec FINE ;
  76:  !bend 'b16' (step 5) ;
  77:J P[13] 100% FINE ;
  78:L P[14] 371mm/sec FINE ;
  79:  !press: pulse output 'bend start' ;
  80:  !(missing in io.outputs) ;
  81:  !press: wait for input 'bend ;
  82:  !done' (missing in io.inputs) ;
  83:L P[15] 371mm/sec FINE ;
  84:  !bend 'b17' (step 6) ;
  85:J P[16] 100% FINE ;
  86:L P[17] 371mm/sec FINE ;
  87:  !press: pulse output 'bend start' ;
  88:  !(missing in io.outputs) ;
  89:  !press: wait for input 'bend ;
  90:  !done' (missing in io.inputs) ;
  91:L P[18] 371mm/sec FINE ;
  92:  !transfer to the pallet as ;
  93:  !planned (checked) ;
  94:J P[19] 100% CNT5 ;
  95:J P[20] 100% CNT5 ;
  96:J P[21] 100% FINE ;
  97:  !unload ;
  98:  !gripper open: the project has no ;
  99:  !io.gripper, add one ;
 100:J P[22] 100% FINE ;
/POS
P[1:"b1_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    405.405421 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[2:"b1_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    555.405421 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[3:"b1_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    405.405421 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[4:"b2_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    405.405421 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[5:"b2_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    555.405421 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[6:"b2_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    405.405421 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[7:"b3_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    448.468474 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =   -180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[8:"b3_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    598.468474 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[9:"b3_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    448.468474 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =   -180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[10:"b4_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    448.468474 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[11:"b4_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    598.468474 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[12:"b4_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    448.468474 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[13:"b5_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    397.172567 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[14:"b5_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    547.172567 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[15:"b5_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    397.172567 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[16:"b6_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    397.172567 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =   -180.000000 deg,	P =      0.000000 deg,	R =   -180.000000 deg
};
P[17:"b6_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    547.172567 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =   -180.000000 deg,	P =      0.000000 deg,	R =    180.000000 deg
};
P[18:"b6_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    397.172567 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =   -180.000000 deg,	P =      0.000000 deg,	R =   -180.000000 deg
};
P[19:"transfer1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    420.000000 mm,	Y =   -400.000000 mm,	Z =    355.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[20:"transfer2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    150.000000 mm,	Y =   -560.000000 mm,	Z =    480.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[21:"pallet"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =      0.000000 mm,	Y =   -650.000000 mm,	Z =    140.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[22:"home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=     90.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
/END
