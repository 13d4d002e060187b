/PROG  PICK_PLACE
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 53;
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
   1:  !workbench program pick_place ;
   2:  !frames (set below from PR): ;
   3:  !UTOOL[1]: gripper ;
   4:  !UT1 mass 2.000 kg ;
   5:  !UT1 cog 0.0,0.0,60.0 mm ;
   6:  !UFRAME[1]: base ;
   7:  PR[90]=LPOS-LPOS ;
   8:  PR[90,1]=0.000000 ;
   9:  PR[90,2]=0.000000 ;
  10:  PR[90,3]=150.000000 ;
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
  23:  !pick a part from the left ;
  24:  !fixture, place it on the right ;
  25:  !one ;
  26:  UTOOL_NUM=1 ;
  27:  UFRAME_NUM=1 ;
  28:J P[1] 10% FINE ;
  29:L P[2] 150mm/sec FINE ;
  30:  !gripper close ;
  31:  DO[1:grip]=ON ;
  32:  $WAITTMOUT=200 ;
  33:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[1] ;
  34:  WAIT 0.20(sec) ;
  35:L P[3] 250mm/sec CR30 ;
  36:L P[4] 400mm/sec CR30 ;
  37:L P[5] 150mm/sec FINE ;
  38:  !gripper open ;
  39:  DO[1:grip]=OFF ;
  40:  $WAITTMOUT=200 ;
  41:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[2] ;
  42:  WAIT 0.20(sec) ;
  43:L P[6] 250mm/sec FINE ;
  44:J P[7] 80% FINE ;
  45:  END ;
  46:  LBL[1] ;
  47:  !timeout DI[1] 2 s ;
  48:  MESSAGE[TIMEOUT DI 1] ;
  49:  ABORT ;
  50:  LBL[2] ;
  51:  !timeout DI[2] 2 s ;
  52:  MESSAGE[TIMEOUT DI 2] ;
  53:  ABORT ;
/POS
P[1:"above_left"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =    180.000000 mm,	Z =    580.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[2:"pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =    180.000000 mm,	Z =    495.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[3:"lift"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =    180.000000 mm,	Z =    580.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[4:"above_right"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =   -180.000000 mm,	Z =    580.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[5:"place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =   -180.000000 mm,	Z =    535.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[6:"retract"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    430.000000 mm,	Y =   -180.000000 mm,	Z =    580.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =      0.000000 deg
};
P[7:"home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=     90.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=    -90.000000 deg,	J6=      0.000000 deg
};
/END
