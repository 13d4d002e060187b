/PROG  BENDING
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 157;
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
   1:  !workbench program bending ;
   2:  !frames (set below from PR): ;
   3:  !UTOOL[1]: suction_gripper ;
   4:  !UT1 mass 2.500 kg ;
   5:  !UT1 cog 0.0,0.0,55.0 mm ;
   6:  !UFRAME[1]: base ;
   7:  PR[90]=LPOS-LPOS ;
   8:  PR[90,1]=0.000000 ;
   9:  PR[90,2]=0.000000 ;
  10:  PR[90,3]=120.000000 ;
  11:  PR[90,4]=0.000000 ;
  12:  PR[90,5]=0.000000 ;
  13:  PR[90,6]=0.000000 ;
  14:  UTOOL[1]=PR[90] ;
  15:  PR[90]=LPOS-LPOS ;
  16:  PR[90,1]=0.000000 ;
  17:  PR[90,2]=0.000000 ;
  18:  PR[90,3]=0.000000 ;
  19:  PR[90,4]=0.000000 ;
  20:  PR[90,5]=0.000000 ;
  21:  PR[90,6]=0.000000 ;
  22:  UFRAME[1]=PR[90] ;
  23:  !bending: 6 bends (front/elbow ;
  24:  !up/flip) ;
  25:  !load: the plan has no blank ;
  26:  !station, the blank is put into ;
  27:  !the gripper here ;
  28:  !gripper close ;
  29:  DO[1:vacuum]=ON ;
  30:  $WAITTMOUT=200 ;
  31:  WAIT DI[1:vacuum_ok]=ON TIMEOUT,LBL[1] ;
  32:  WAIT 0.30(sec) ;
  33:  !bend 'b23' (step 1) ;
  34:  UTOOL_NUM=1 ;
  35:  UFRAME_NUM=1 ;
  36:J P[1] 10% FINE ;
  37:L P[2] 250mm/sec FINE ;
  38:  DO[2:press_start]=ON ;
  39:  $WAITTMOUT=3000 ;
  40:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[2] ;
  41:  DO[2:press_start]=OFF ;
  42:  $WAITTMOUT=3000 ;
  43:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[3] ;
  44:L P[3] 250mm/sec FINE ;
  45:  !bend 'b45' (step 2) ;
  46:J P[4] 50% FINE ;
  47:L P[5] 250mm/sec FINE ;
  48:  DO[2:press_start]=ON ;
  49:  $WAITTMOUT=3000 ;
  50:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[4] ;
  51:  DO[2:press_start]=OFF ;
  52:  $WAITTMOUT=3000 ;
  53:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[5] ;
  54:L P[6] 250mm/sec FINE ;
  55:  !bend 'b12' (step 3) ;
  56:J P[7] 50% FINE ;
  57:L P[8] 250mm/sec FINE ;
  58:  DO[2:press_start]=ON ;
  59:  $WAITTMOUT=3000 ;
  60:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[6] ;
  61:  DO[2:press_start]=OFF ;
  62:  $WAITTMOUT=3000 ;
  63:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[7] ;
  64:L P[9] 250mm/sec FINE ;
  65:  !bend 'b14' (step 4) ;
  66:J P[10] 50% FINE ;
  67:L P[11] 250mm/sec FINE ;
  68:  DO[2:press_start]=ON ;
  69:  $WAITTMOUT=3000 ;
  70:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[8] ;
  71:  DO[2:press_start]=OFF ;
  72:  $WAITTMOUT=3000 ;
  73:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[9] ;
  74:L P[12] 250mm/sec FINE ;
  75:  !bend 'b16' (step 5) ;
  76:J P[13] 50% FINE ;
  77:L P[14] 250mm/sec FINE ;
  78:  DO[2:press_start]=ON ;
  79:  $WAITTMOUT=3000 ;
  80:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[10] ;
  81:  DO[2:press_start]=OFF ;
  82:  $WAITTMOUT=3000 ;
  83:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[11] ;
  84:L P[15] 250mm/sec FINE ;
  85:  !bend 'b17' (step 6) ;
  86:J P[16] 50% FINE ;
  87:L P[17] 250mm/sec FINE ;
  88:  DO[2:press_start]=ON ;
  89:  $WAITTMOUT=3000 ;
  90:  WAIT DI[3:press_clamped]=ON TIMEOUT,LBL[12] ;
  91:  DO[2:press_start]=OFF ;
  92:  $WAITTMOUT=3000 ;
  93:  WAIT DI[2:press_done]=ON TIMEOUT,LBL[13] ;
  94:L P[18] 250mm/sec FINE ;
  95:  !transfer to the pallet as ;
  96:  !planned (checked) ;
  97:J P[19] 100% CNT100 ;
  98:J P[20] 100% CNT100 ;
  99:J P[21] 100% FINE ;
 100:  !unload ;
 101:  !gripper open ;
 102:  DO[1:vacuum]=OFF ;
 103:  WAIT 0.30(sec) ;
 104:J P[22] 50% FINE ;
 105:  END ;
 106:  LBL[1] ;
 107:  !timeout DI[1] 2 s ;
 108:  MESSAGE[TIMEOUT DI 1] ;
 109:  ABORT ;
 110:  LBL[2] ;
 111:  !timeout DI[3] 30 s ;
 112:  MESSAGE[TIMEOUT DI 3] ;
 113:  ABORT ;
 114:  LBL[3] ;
 115:  !timeout DI[2] 30 s ;
 116:  MESSAGE[TIMEOUT DI 2] ;
 117:  ABORT ;
 118:  LBL[4] ;
 119:  !timeout DI[3] 30 s ;
 120:  MESSAGE[TIMEOUT DI 3] ;
 121:  ABORT ;
 122:  LBL[5] ;
 123:  !timeout DI[2] 30 s ;
 124:  MESSAGE[TIMEOUT DI 2] ;
 125:  ABORT ;
 126:  LBL[6] ;
 127:  !timeout DI[3] 30 s ;
 128:  MESSAGE[TIMEOUT DI 3] ;
 129:  ABORT ;
 130:  LBL[7] ;
 131:  !timeout DI[2] 30 s ;
 132:  MESSAGE[TIMEOUT DI 2] ;
 133:  ABORT ;
 134:  LBL[8] ;
 135:  !timeout DI[3] 30 s ;
 136:  MESSAGE[TIMEOUT DI 3] ;
 137:  ABORT ;
 138:  LBL[9] ;
 139:  !timeout DI[2] 30 s ;
 140:  MESSAGE[TIMEOUT DI 2] ;
 141:  ABORT ;
 142:  LBL[10] ;
 143:  !timeout DI[3] 30 s ;
 144:  MESSAGE[TIMEOUT DI 3] ;
 145:  ABORT ;
 146:  LBL[11] ;
 147:  !timeout DI[2] 30 s ;
 148:  MESSAGE[TIMEOUT DI 2] ;
 149:  ABORT ;
 150:  LBL[12] ;
 151:  !timeout DI[3] 30 s ;
 152:  MESSAGE[TIMEOUT DI 3] ;
 153:  ABORT ;
 154:  LBL[13] ;
 155:  !timeout DI[2] 30 s ;
 156:  MESSAGE[TIMEOUT DI 2] ;
 157:  ABORT ;
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
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
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
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
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
	W =    180.000000 deg,	P =      0.000000 deg,	R =    180.000000 deg
};
P[17:"b6_bend"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    547.172567 mm,	Y =      0.000000 mm,	Z =    351.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    180.000000 deg
};
P[18:"b6_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    397.172567 mm,	Y =      0.000000 mm,	Z =    411.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    180.000000 deg
};
P[19:"transfer1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    420.000000 mm,	Y =   -400.000000 mm,	Z =    440.000000 mm,
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
