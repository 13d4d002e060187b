/PROG  PICK_PLACE
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 7;
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
   1:J P[1] 60% CNT20 ;  ! above_left
   2:L P[2] 150mm/sec FINE ;  ! pick
   3:L P[3] 250mm/sec CNT30 ;  ! lift
   4:L P[4] 400mm/sec CNT30 ;  ! above_right
   5:L P[5] 150mm/sec FINE ;  ! place
   6:L P[6] 250mm/sec FINE ;  ! retract
   7:J P[7] 80% FINE ;  ! home
/POS
P[1 : "above_left"]{
   GP1:
	UF : 0, UT : 1,
	J1=   22.714 deg,	J2=  -21.271 deg,	J3=   43.924 deg,
	J4=    0.000 deg,	J5=   22.653 deg,	J6=  -22.714 deg
};
P[2 : "pick"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.000  mm,	Y =  180.000  mm,	Z =  495.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =    0.000 deg
};
P[3 : "lift"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.000  mm,	Y =  180.000  mm,	Z =  580.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =    0.000 deg
};
P[4 : "above_right"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.000  mm,	Y = -180.000  mm,	Z =  580.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =    0.000 deg
};
P[5 : "place"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.000  mm,	Y = -180.000  mm,	Z =  535.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =    0.000 deg
};
P[6 : "retract"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.000  mm,	Y = -180.000  mm,	Z =  580.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =    0.000 deg
};
P[7 : "home"]{
   GP1:
	UF : 0, UT : 1,
	J1=    0.000 deg,	J2=    0.000 deg,	J3=    0.000 deg,
	J4=    0.000 deg,	J5=    0.000 deg,	J6=    0.000 deg
};
/END
