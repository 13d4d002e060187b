/PROG  DEMO
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 4;
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
   1:J P[1] 50% FINE ;  ! home
   2:L P[2] 250mm/sec CNT10 ;  ! approach
   3:L P[3] 100mm/sec FINE ;  ! pick
   4:J P[4] 100% CNT25 ;  ! leave
/POS
P[1 : "home"]{
   GP1:
	UF : 0, UT : 1,
	J1=    0.000 deg,	J2=  -30.000 deg,	J3=   60.000 deg,
	J4=    0.000 deg,	J5=   45.000 deg,	J6=    0.000 deg
};
P[2 : "approach"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.000  mm,	Y =  100.000  mm,	Z =  400.000  mm,
	W =  180.000 deg,	P =    0.000 deg,	R =   90.000 deg
};
P[3 : "pick"]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.000  mm,	Y = -200.000  mm,	Z =  300.000  mm,
	W =  170.000 deg,	P =   10.000 deg,	R =   45.000 deg
};
P[4 : "leave"]{
   GP1:
	UF : 0, UT : 1,
	J1=   10.000 deg,	J2=  -20.000 deg,	J3=   50.000 deg,
	J4=    5.000 deg,	J5=   40.000 deg,	J6=   -5.000 deg
};
/END
