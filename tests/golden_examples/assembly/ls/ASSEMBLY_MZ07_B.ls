/PROG  ASSEMBLY_MZ07_B
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 229;
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
   1:  !note: TCP speed rounded to the ;
   2:  !controller's steps on 6 lines, ;
   3:  !the largest: program ;
   4:  !assembly_MZ07_B, move 42 ;
   5:  !(t2_retreat): TCP speed 209.418 ;
   6:  !mm/s written as 209 mm/s ;
   7:  !workbench program ;
   8:  !assembly_MZ07_B ;
   9:  !frames (set below from PR): ;
  10:  !UTOOL[1]: MZ07_B_tool ;
  11:  !UT1 mass 1.200 kg ;
  12:  !UT1 cog 0.0,0.0,60.0 mm ;
  13:  !UFRAME[1]: base ;
  14:  PR[90]=LPOS-LPOS ;
  15:  PR[90,1]=0.000000 ;
  16:  PR[90,2]=0.000000 ;
  17:  PR[90,3]=150.000000 ;
  18:  PR[90,4]=0.000000 ;
  19:  PR[90,5]=0.000000 ;
  20:  PR[90,6]=0.000000 ;
  21:  UTOOL[1]=PR[90] ;
  22:  PR[90]=LPOS-LPOS ;
  23:  PR[90,1]=0.000000 ;
  24:  PR[90,2]=0.000000 ;
  25:  PR[90,3]=0.000000 ;
  26:  PR[90,4]=0.000000 ;
  27:  PR[90,5]=0.000000 ;
  28:  PR[90,6]=0.000000 ;
  29:  UFRAME[1]=PR[90] ;
  30:  !SYNC sync1: ;
  31:  !assembly_MZ07,assembly_MZ07_B ;
  32:  WAIT DI[10:sync_b_in]=ON ;
  33:  DO[10:sync_b]=ON ;
  34:  WAIT DI[10:sync_b_in]=OFF ;
  35:  DO[10:sync_b]=OFF ;
  36:  !task 2: plate_b ;
  37:  UTOOL_NUM=1 ;
  38:  UFRAME_NUM=1 ;
  39:J P[1] 10% FINE ;
  40:L P[2] 279mm/sec FINE ;
  41:  !gripper close ;
  42:  DO[1:grip]=ON ;
  43:  $WAITTMOUT=200 ;
  44:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[1] ;
  45:  WAIT 0.20(sec) ;
  46:J P[3] 100% CNT100 ;
  47:J P[4] 100% CNT100 ;
  48:J P[5] 100% CNT100 ;
  49:J P[6] 100% CNT100 ;
  50:J P[7] 100% CNT100 ;
  51:J P[8] 100% CNT100 ;
  52:J P[9] 100% CNT100 ;
  53:J P[10] 100% CNT100 ;
  54:J P[11] 100% CNT100 ;
  55:J P[12] 100% CNT100 ;
  56:J P[13] 100% CNT100 ;
  57:J P[14] 100% CNT100 ;
  58:J P[15] 100% CNT100 ;
  59:J P[16] 100% CNT100 ;
  60:J P[17] 100% CNT100 ;
  61:J P[18] 100% CNT100 ;
  62:J P[19] 100% CNT100 ;
  63:J P[20] 100% CNT100 ;
  64:J P[21] 100% CNT100 ;
  65:J P[22] 100% CNT100 ;
  66:J P[23] 100% CNT100 ;
  67:J P[24] 100% CNT100 ;
  68:J P[25] 100% CNT100 ;
  69:J P[26] 100% CNT100 ;
  70:J P[27] 100% CNT100 ;
  71:J P[28] 100% CNT100 ;
  72:J P[29] 100% CNT100 ;
  73:J P[30] 100% CNT100 ;
  74:J P[31] 100% CNT100 ;
  75:J P[32] 100% CNT100 ;
  76:J P[33] 100% CNT100 ;
  77:J P[34] 100% CNT100 ;
  78:J P[35] 100% CNT100 ;
  79:J P[36] 100% CNT100 ;
  80:J P[37] 100% CNT100 ;
  81:J P[38] 100% CNT100 ;
  82:J P[39] 100% CNT100 ;
  83:J P[40] 100% CNT100 ;
  84:J P[41] 100% CNT100 ;
  85:J P[42] 100% FINE ;
  86:  !gripper open ;
  87:  DO[1:grip]=OFF ;
  88:  $WAITTMOUT=200 ;
  89:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[2] ;
  90:  WAIT 0.20(sec) ;
  91:L P[43] 209mm/sec FINE ;
  92:J P[44] 100% FINE ;
  93:  !SYNC sync2: ;
  94:  !assembly_MZ07_B,assembly_MZ07 ;
  95:  WAIT DI[10:sync_b_in]=ON ;
  96:  DO[10:sync_b]=ON ;
  97:  WAIT DI[10:sync_b_in]=OFF ;
  98:  DO[10:sync_b]=OFF ;
  99:  !SYNC sync3: ;
 100:  !assembly_MZ07,assembly_MZ07_B ;
 101:  WAIT DI[10:sync_b_in]=ON ;
 102:  DO[10:sync_b]=ON ;
 103:  WAIT DI[10:sync_b_in]=OFF ;
 104:  DO[10:sync_b]=OFF ;
 105:  !task 5: screw_2 ;
 106:J P[45] 100% FINE ;
 107:L P[46] 171mm/sec FINE ;
 108:  !gripper close ;
 109:  DO[1:grip]=ON ;
 110:  $WAITTMOUT=200 ;
 111:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[3] ;
 112:  WAIT 0.20(sec) ;
 113:J P[47] 100% CNT100 ;
 114:J P[48] 100% CNT100 ;
 115:J P[49] 100% CNT100 ;
 116:J P[50] 100% CNT100 ;
 117:J P[51] 100% CNT100 ;
 118:J P[52] 100% CNT100 ;
 119:J P[53] 100% CNT100 ;
 120:J P[54] 100% CNT100 ;
 121:J P[55] 100% CNT100 ;
 122:J P[56] 100% CNT100 ;
 123:J P[57] 100% CNT100 ;
 124:J P[58] 100% CNT100 ;
 125:J P[59] 100% CNT100 ;
 126:J P[60] 100% CNT100 ;
 127:J P[61] 100% CNT100 ;
 128:J P[62] 100% CNT100 ;
 129:J P[63] 100% CNT100 ;
 130:J P[64] 100% CNT100 ;
 131:J P[65] 100% CNT100 ;
 132:J P[66] 100% CNT100 ;
 133:J P[67] 100% CNT100 ;
 134:J P[68] 100% FINE ;
 135:  !gripper open ;
 136:  DO[1:grip]=OFF ;
 137:  $WAITTMOUT=200 ;
 138:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[4] ;
 139:  WAIT 0.20(sec) ;
 140:L P[69] 263mm/sec FINE ;
 141:J P[70] 100% FINE ;
 142:  !task 6: screw_3 ;
 143:J P[71] 100% FINE ;
 144:L P[72] 175mm/sec FINE ;
 145:  !gripper close ;
 146:  DO[1:grip]=ON ;
 147:  $WAITTMOUT=200 ;
 148:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[5] ;
 149:  WAIT 0.20(sec) ;
 150:J P[73] 100% CNT100 ;
 151:J P[74] 100% CNT100 ;
 152:J P[75] 100% CNT100 ;
 153:J P[76] 100% CNT100 ;
 154:J P[77] 100% CNT100 ;
 155:J P[78] 100% CNT100 ;
 156:J P[79] 100% CNT100 ;
 157:J P[80] 100% CNT100 ;
 158:J P[81] 100% CNT100 ;
 159:J P[82] 100% CNT100 ;
 160:J P[83] 100% CNT100 ;
 161:J P[84] 100% CNT100 ;
 162:J P[85] 100% CNT100 ;
 163:J P[86] 100% CNT100 ;
 164:J P[87] 100% CNT100 ;
 165:J P[88] 100% CNT100 ;
 166:J P[89] 100% CNT100 ;
 167:J P[90] 100% CNT100 ;
 168:J P[91] 100% CNT100 ;
 169:J P[92] 100% CNT100 ;
 170:J P[93] 100% CNT100 ;
 171:J P[94] 100% CNT100 ;
 172:J P[95] 100% CNT100 ;
 173:J P[96] 100% CNT100 ;
 174:J P[97] 100% CNT100 ;
 175:J P[98] 100% CNT100 ;
 176:J P[99] 100% CNT100 ;
 177:J P[100] 100% CNT100 ;
 178:J P[101] 100% CNT100 ;
 179:J P[102] 100% CNT100 ;
 180:J P[103] 100% CNT100 ;
 181:J P[104] 100% CNT100 ;
 182:J P[105] 100% CNT100 ;
 183:J P[106] 100% CNT100 ;
 184:J P[107] 100% CNT100 ;
 185:J P[108] 100% CNT100 ;
 186:J P[109] 100% CNT100 ;
 187:J P[110] 100% CNT100 ;
 188:J P[111] 100% CNT100 ;
 189:J P[112] 100% CNT100 ;
 190:J P[113] 100% CNT100 ;
 191:J P[114] 100% FINE ;
 192:  !gripper open ;
 193:  DO[1:grip]=OFF ;
 194:  $WAITTMOUT=200 ;
 195:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[6] ;
 196:  WAIT 0.20(sec) ;
 197:L P[115] 263mm/sec FINE ;
 198:J P[116] 100% FINE ;
 199:  !SYNC sync4: ;
 200:  !assembly_MZ07_B,assembly_MZ07 ;
 201:  WAIT DI[10:sync_b_in]=ON ;
 202:  DO[10:sync_b]=ON ;
 203:  WAIT DI[10:sync_b_in]=OFF ;
 204:  DO[10:sync_b]=OFF ;
 205:  END ;
 206:  LBL[1] ;
 207:  !timeout DI[1] 2 s ;
 208:  MESSAGE[TIMEOUT DI 1] ;
 209:  ABORT ;
 210:  LBL[2] ;
 211:  !timeout DI[2] 2 s ;
 212:  MESSAGE[TIMEOUT DI 2] ;
 213:  ABORT ;
 214:  LBL[3] ;
 215:  !timeout DI[1] 2 s ;
 216:  MESSAGE[TIMEOUT DI 1] ;
 217:  ABORT ;
 218:  LBL[4] ;
 219:  !timeout DI[2] 2 s ;
 220:  MESSAGE[TIMEOUT DI 2] ;
 221:  ABORT ;
 222:  LBL[5] ;
 223:  !timeout DI[1] 2 s ;
 224:  MESSAGE[TIMEOUT DI 1] ;
 225:  ABORT ;
 226:  LBL[6] ;
 227:  !timeout DI[2] 2 s ;
 228:  MESSAGE[TIMEOUT DI 2] ;
 229:  ABORT ;
/POS
P[1:"t2_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    270.000000 mm,	Y =    330.000000 mm,	Z =    465.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     70.000000 deg
};
P[2:"t2_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    270.000000 mm,	Y =    330.000000 mm,	Z =    415.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     70.000000 deg
};
P[3:"t2_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    278.250000 mm,	Y =    321.750000 mm,	Z =    413.925000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     70.500000 deg
};
P[4:"t2_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.500000 mm,	Y =    313.500000 mm,	Z =    412.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     71.000000 deg
};
P[5:"t2_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    294.750000 mm,	Y =    305.250000 mm,	Z =    411.775000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     71.500000 deg
};
P[6:"t2_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    303.000000 mm,	Y =    297.000000 mm,	Z =    410.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     72.000000 deg
};
P[7:"t2_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    311.250000 mm,	Y =    288.750000 mm,	Z =    409.625000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     72.500000 deg
};
P[8:"t2_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    319.500000 mm,	Y =    280.500000 mm,	Z =    408.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     73.000000 deg
};
P[9:"t2_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    327.750000 mm,	Y =    272.250000 mm,	Z =    407.475000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     73.500000 deg
};
P[10:"t2_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    336.000000 mm,	Y =    264.000000 mm,	Z =    406.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     74.000000 deg
};
P[11:"t2_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    344.250000 mm,	Y =    255.750000 mm,	Z =    405.325000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     74.500000 deg
};
P[12:"t2_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    352.500000 mm,	Y =    247.500000 mm,	Z =    404.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     75.000000 deg
};
P[13:"t2_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    360.750000 mm,	Y =    239.250000 mm,	Z =    403.175000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     75.500000 deg
};
P[14:"t2_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    369.000000 mm,	Y =    231.000000 mm,	Z =    402.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     76.000000 deg
};
P[15:"t2_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    377.250000 mm,	Y =    222.750000 mm,	Z =    401.025000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     76.500000 deg
};
P[16:"t2_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    385.500000 mm,	Y =    214.500000 mm,	Z =    399.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     77.000000 deg
};
P[17:"t2_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    393.750000 mm,	Y =    206.250000 mm,	Z =    398.875000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     77.500000 deg
};
P[18:"t2_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    402.000000 mm,	Y =    198.000000 mm,	Z =    397.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     78.000000 deg
};
P[19:"t2_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    410.250000 mm,	Y =    189.750000 mm,	Z =    396.725000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     78.500000 deg
};
P[20:"t2_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    418.500000 mm,	Y =    181.500000 mm,	Z =    395.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     79.000000 deg
};
P[21:"t2_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    426.750000 mm,	Y =    173.250000 mm,	Z =    394.575000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     79.500000 deg
};
P[22:"t2_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    435.000000 mm,	Y =    165.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     80.000000 deg
};
P[23:"t2_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    443.250000 mm,	Y =    156.750000 mm,	Z =    392.425000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     80.500000 deg
};
P[24:"t2_c22"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    451.500000 mm,	Y =    148.500000 mm,	Z =    391.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     81.000000 deg
};
P[25:"t2_c23"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    459.750000 mm,	Y =    140.250000 mm,	Z =    390.275000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     81.500000 deg
};
P[26:"t2_c24"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    468.000000 mm,	Y =    132.000000 mm,	Z =    389.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     82.000000 deg
};
P[27:"t2_c25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    476.250000 mm,	Y =    123.750000 mm,	Z =    388.125000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     82.500000 deg
};
P[28:"t2_c26"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    484.500000 mm,	Y =    115.500000 mm,	Z =    387.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     83.000000 deg
};
P[29:"t2_c27"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    492.750000 mm,	Y =    107.250000 mm,	Z =    385.975000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     83.500000 deg
};
P[30:"t2_c28"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    501.000000 mm,	Y =     99.000000 mm,	Z =    384.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     84.000000 deg
};
P[31:"t2_c29"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    509.250000 mm,	Y =     90.750000 mm,	Z =    383.825000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     84.500000 deg
};
P[32:"t2_c30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    517.500000 mm,	Y =     82.500000 mm,	Z =    382.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     85.000000 deg
};
P[33:"t2_c31"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    525.750000 mm,	Y =     74.250000 mm,	Z =    381.675000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     85.500000 deg
};
P[34:"t2_c32"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    534.000000 mm,	Y =     66.000000 mm,	Z =    380.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     86.000000 deg
};
P[35:"t2_c33"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    542.250000 mm,	Y =     57.750000 mm,	Z =    379.525000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     86.500000 deg
};
P[36:"t2_c34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.500000 mm,	Y =     49.500000 mm,	Z =    378.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     87.000000 deg
};
P[37:"t2_c35"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    558.750000 mm,	Y =     41.250000 mm,	Z =    377.375000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     87.500000 deg
};
P[38:"t2_c36"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    567.000000 mm,	Y =     33.000000 mm,	Z =    376.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     88.000000 deg
};
P[39:"t2_c37"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    575.250000 mm,	Y =     24.750000 mm,	Z =    375.225000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     88.500000 deg
};
P[40:"t2_c38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    583.500000 mm,	Y =     16.500000 mm,	Z =    374.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     89.000000 deg
};
P[41:"t2_c39"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    591.750000 mm,	Y =      8.250000 mm,	Z =    373.075000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     89.500000 deg
};
P[42:"t2_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =      0.000000 mm,	Z =    372.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[43:"t2_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =      0.000000 mm,	Z =    422.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[44:"t2_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
P[45:"t5_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -200.000000 mm,	Z =    508.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    120.000000 deg
};
P[46:"t5_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -200.000000 mm,	Z =    458.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    120.000000 deg
};
P[47:"t5_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    236.500000 mm,	Y =   -193.750000 mm,	Z =    455.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    118.500000 deg
};
P[48:"t5_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    253.000000 mm,	Y =   -187.500000 mm,	Z =    453.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    117.000000 deg
};
P[49:"t5_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    269.500000 mm,	Y =   -181.250000 mm,	Z =    450.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    115.500000 deg
};
P[50:"t5_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.000000 mm,	Y =   -175.000000 mm,	Z =    448.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    114.000000 deg
};
P[51:"t5_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    302.500000 mm,	Y =   -168.750000 mm,	Z =    445.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    112.500000 deg
};
P[52:"t5_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    319.000000 mm,	Y =   -162.500000 mm,	Z =    443.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    111.000000 deg
};
P[53:"t5_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    335.500000 mm,	Y =   -156.250000 mm,	Z =    440.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    109.500000 deg
};
P[54:"t5_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    352.000000 mm,	Y =   -150.000000 mm,	Z =    438.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    108.000000 deg
};
P[55:"t5_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    368.500000 mm,	Y =   -143.750000 mm,	Z =    435.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    106.500000 deg
};
P[56:"t5_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    385.000000 mm,	Y =   -137.500000 mm,	Z =    433.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    105.000000 deg
};
P[57:"t5_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    401.500000 mm,	Y =   -131.250000 mm,	Z =    431.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    103.500000 deg
};
P[58:"t5_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    418.000000 mm,	Y =   -125.000000 mm,	Z =    428.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    102.000000 deg
};
P[59:"t5_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    434.500000 mm,	Y =   -118.750000 mm,	Z =    426.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    100.500000 deg
};
P[60:"t5_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    451.000000 mm,	Y =   -112.500000 mm,	Z =    423.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     99.000000 deg
};
P[61:"t5_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    467.500000 mm,	Y =   -106.250000 mm,	Z =    421.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     97.500000 deg
};
P[62:"t5_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    484.000000 mm,	Y =   -100.000000 mm,	Z =    418.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     96.000000 deg
};
P[63:"t5_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    500.500000 mm,	Y =    -93.750000 mm,	Z =    416.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     94.500000 deg
};
P[64:"t5_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    517.000000 mm,	Y =    -87.500000 mm,	Z =    413.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     93.000000 deg
};
P[65:"t5_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    533.500000 mm,	Y =    -81.250000 mm,	Z =    411.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     91.500000 deg
};
P[66:"t5_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    409.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[67:"t5_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[68:"t5_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    378.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[69:"t5_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    428.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[70:"t5_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
P[71:"t6_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -260.000000 mm,	Z =    508.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    135.000000 deg
};
P[72:"t6_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -260.000000 mm,	Z =    458.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    135.000000 deg
};
P[73:"t6_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    228.250000 mm,	Y =   -251.625000 mm,	Z =    456.775000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    133.875000 deg
};
P[74:"t6_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    236.500000 mm,	Y =   -243.250000 mm,	Z =    455.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    132.750000 deg
};
P[75:"t6_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    244.750000 mm,	Y =   -234.875000 mm,	Z =    454.325000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    131.625000 deg
};
P[76:"t6_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    253.000000 mm,	Y =   -226.500000 mm,	Z =    453.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    130.500000 deg
};
P[77:"t6_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    261.250000 mm,	Y =   -218.125000 mm,	Z =    451.875000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    129.375000 deg
};
P[78:"t6_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    269.500000 mm,	Y =   -209.750000 mm,	Z =    450.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    128.250000 deg
};
P[79:"t6_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    277.750000 mm,	Y =   -201.375000 mm,	Z =    449.425000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    127.125000 deg
};
P[80:"t6_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    286.000000 mm,	Y =   -193.000000 mm,	Z =    448.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    126.000000 deg
};
P[81:"t6_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    294.250000 mm,	Y =   -184.625000 mm,	Z =    446.975000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    124.875000 deg
};
P[82:"t6_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    302.500000 mm,	Y =   -176.250000 mm,	Z =    445.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    123.750000 deg
};
P[83:"t6_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    310.750000 mm,	Y =   -167.875000 mm,	Z =    444.525000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    122.625000 deg
};
P[84:"t6_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    319.000000 mm,	Y =   -159.500000 mm,	Z =    443.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    121.500000 deg
};
P[85:"t6_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    327.250000 mm,	Y =   -151.125000 mm,	Z =    442.075000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    120.375000 deg
};
P[86:"t6_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    335.500000 mm,	Y =   -142.750000 mm,	Z =    440.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    119.250000 deg
};
P[87:"t6_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    343.750000 mm,	Y =   -134.375000 mm,	Z =    439.625000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    118.125000 deg
};
P[88:"t6_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    352.000000 mm,	Y =   -126.000000 mm,	Z =    438.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    117.000000 deg
};
P[89:"t6_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    360.250000 mm,	Y =   -117.625000 mm,	Z =    437.175000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    115.875000 deg
};
P[90:"t6_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    368.500000 mm,	Y =   -109.250000 mm,	Z =    435.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    114.750000 deg
};
P[91:"t6_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    376.750000 mm,	Y =   -100.875000 mm,	Z =    434.725000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    113.625000 deg
};
P[92:"t6_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    385.000000 mm,	Y =    -92.500000 mm,	Z =    433.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    112.500000 deg
};
P[93:"t6_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    393.250000 mm,	Y =    -84.125000 mm,	Z =    432.275000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    111.375000 deg
};
P[94:"t6_c22"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    401.500000 mm,	Y =    -75.750000 mm,	Z =    431.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    110.250000 deg
};
P[95:"t6_c23"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    409.750000 mm,	Y =    -67.375000 mm,	Z =    429.825000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    109.125000 deg
};
P[96:"t6_c24"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    418.000000 mm,	Y =    -59.000000 mm,	Z =    428.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    108.000000 deg
};
P[97:"t6_c25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    426.250000 mm,	Y =    -50.625000 mm,	Z =    427.375000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    106.875000 deg
};
P[98:"t6_c26"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    434.500000 mm,	Y =    -42.250000 mm,	Z =    426.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    105.750000 deg
};
P[99:"t6_c27"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    442.750000 mm,	Y =    -33.875000 mm,	Z =    424.925000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    104.625000 deg
};
P[100:"t6_c28"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    451.000000 mm,	Y =    -25.500000 mm,	Z =    423.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    103.500000 deg
};
P[101:"t6_c29"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    459.250000 mm,	Y =    -17.125000 mm,	Z =    422.475000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    102.375000 deg
};
P[102:"t6_c30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    467.500000 mm,	Y =     -8.750000 mm,	Z =    421.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    101.250000 deg
};
P[103:"t6_c31"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    475.750000 mm,	Y =     -0.375000 mm,	Z =    420.025000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    100.125000 deg
};
P[104:"t6_c32"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    484.000000 mm,	Y =      8.000000 mm,	Z =    418.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     99.000000 deg
};
P[105:"t6_c33"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    492.250000 mm,	Y =     16.375000 mm,	Z =    417.575000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     97.875000 deg
};
P[106:"t6_c34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    500.500000 mm,	Y =     24.750000 mm,	Z =    416.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     96.750000 deg
};
P[107:"t6_c35"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    508.750000 mm,	Y =     33.125000 mm,	Z =    415.125000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     95.625000 deg
};
P[108:"t6_c36"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    517.000000 mm,	Y =     41.500000 mm,	Z =    413.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     94.500000 deg
};
P[109:"t6_c37"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    525.250000 mm,	Y =     49.875000 mm,	Z =    412.675000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     93.375000 deg
};
P[110:"t6_c38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    533.500000 mm,	Y =     58.250000 mm,	Z =    411.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     92.250000 deg
};
P[111:"t6_c39"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    541.750000 mm,	Y =     66.625000 mm,	Z =    410.225000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     91.125000 deg
};
P[112:"t6_c40"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    409.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[113:"t6_c41"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[114:"t6_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    378.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[115:"t6_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 1',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    428.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =     90.000000 deg
};
P[116:"t6_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
/END
