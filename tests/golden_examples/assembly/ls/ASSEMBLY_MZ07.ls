/PROG  ASSEMBLY_MZ07
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 293;
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
   2:  !controller's steps on 8 lines, ;
   3:  !the largest: program ;
   4:  !assembly_MZ07, move 42 ;
   5:  !(t1_retreat): TCP speed 233.451 ;
   6:  !mm/s written as 233 mm/s ;
   7:  !workbench program assembly_MZ07 ;
   8:  !frames (set below from PR): ;
   9:  !UTOOL[1]: gripper ;
  10:  !UT1 mass 1.200 kg ;
  11:  !UT1 cog 0.0,0.0,60.0 mm ;
  12:  !UFRAME[1]: base ;
  13:  PR[90]=LPOS-LPOS ;
  14:  PR[90,1]=0.000000 ;
  15:  PR[90,2]=0.000000 ;
  16:  PR[90,3]=150.000000 ;
  17:  PR[90,4]=0.000000 ;
  18:  PR[90,5]=0.000000 ;
  19:  PR[90,6]=0.000000 ;
  20:  UTOOL[1]=PR[90] ;
  21:  PR[90]=LPOS-LPOS ;
  22:  PR[90,1]=0.000000 ;
  23:  PR[90,2]=0.000000 ;
  24:  PR[90,3]=0.000000 ;
  25:  PR[90,4]=0.000000 ;
  26:  PR[90,5]=0.000000 ;
  27:  PR[90,6]=0.000000 ;
  28:  UFRAME[1]=PR[90] ;
  29:  !task 1: plate_a ;
  30:  UTOOL_NUM=1 ;
  31:  UFRAME_NUM=1 ;
  32:J P[1] 10% FINE ;
  33:L P[2] 279mm/sec FINE ;
  34:  !gripper close ;
  35:  DO[1:grip]=ON ;
  36:  $WAITTMOUT=200 ;
  37:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[1] ;
  38:  WAIT 0.20(sec) ;
  39:J P[3] 100% CNT100 ;
  40:J P[4] 100% CNT100 ;
  41:J P[5] 100% CNT100 ;
  42:J P[6] 100% CNT100 ;
  43:J P[7] 100% CNT100 ;
  44:J P[8] 100% CNT100 ;
  45:J P[9] 100% CNT100 ;
  46:J P[10] 100% CNT100 ;
  47:J P[11] 100% CNT100 ;
  48:J P[12] 100% CNT100 ;
  49:J P[13] 100% CNT100 ;
  50:J P[14] 100% CNT100 ;
  51:J P[15] 100% CNT100 ;
  52:J P[16] 100% CNT100 ;
  53:J P[17] 100% CNT100 ;
  54:J P[18] 100% CNT100 ;
  55:J P[19] 100% CNT100 ;
  56:J P[20] 100% CNT100 ;
  57:J P[21] 100% CNT100 ;
  58:J P[22] 100% CNT100 ;
  59:J P[23] 100% CNT100 ;
  60:J P[24] 100% CNT100 ;
  61:J P[25] 100% CNT100 ;
  62:J P[26] 100% CNT100 ;
  63:J P[27] 100% CNT100 ;
  64:J P[28] 100% CNT100 ;
  65:J P[29] 100% CNT100 ;
  66:J P[30] 100% CNT100 ;
  67:J P[31] 100% CNT100 ;
  68:J P[32] 100% CNT100 ;
  69:J P[33] 100% CNT100 ;
  70:J P[34] 100% CNT100 ;
  71:J P[35] 100% CNT100 ;
  72:J P[36] 100% CNT100 ;
  73:J P[37] 100% CNT100 ;
  74:J P[38] 100% CNT100 ;
  75:J P[39] 100% CNT100 ;
  76:J P[40] 100% CNT100 ;
  77:J P[41] 100% CNT100 ;
  78:J P[42] 100% FINE ;
  79:  !gripper open ;
  80:  DO[1:grip]=OFF ;
  81:  $WAITTMOUT=200 ;
  82:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[2] ;
  83:  WAIT 0.20(sec) ;
  84:L P[43] 233mm/sec FINE ;
  85:J P[44] 100% FINE ;
  86:  !SYNC sync1: ;
  87:  !assembly_MZ07,assembly_MZ07_B ;
  88:  WAIT DI[10:sync_a_in]=OFF ;
  89:  DO[10:sync_a]=ON ;
  90:  WAIT DI[10:sync_a_in]=ON ;
  91:  DO[10:sync_a]=OFF ;
  92:  !SYNC sync2: ;
  93:  !assembly_MZ07_B,assembly_MZ07 ;
  94:  WAIT DI[10:sync_a_in]=OFF ;
  95:  DO[10:sync_a]=ON ;
  96:  WAIT DI[10:sync_a_in]=ON ;
  97:  DO[10:sync_a]=OFF ;
  98:  !task 3: screw_0 ;
  99:J P[45] 100% FINE ;
 100:L P[46] 171mm/sec FINE ;
 101:  !gripper close ;
 102:  DO[1:grip]=ON ;
 103:  $WAITTMOUT=200 ;
 104:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[3] ;
 105:  WAIT 0.20(sec) ;
 106:J P[47] 100% CNT100 ;
 107:J P[48] 100% CNT100 ;
 108:J P[49] 100% CNT100 ;
 109:J P[50] 100% CNT100 ;
 110:J P[51] 100% CNT100 ;
 111:J P[52] 100% CNT100 ;
 112:J P[53] 100% CNT100 ;
 113:J P[54] 100% CNT100 ;
 114:J P[55] 100% CNT100 ;
 115:J P[56] 100% CNT100 ;
 116:J P[57] 100% CNT100 ;
 117:J P[58] 100% CNT100 ;
 118:J P[59] 100% CNT100 ;
 119:J P[60] 100% CNT100 ;
 120:J P[61] 100% CNT100 ;
 121:J P[62] 100% CNT100 ;
 122:J P[63] 100% CNT100 ;
 123:J P[64] 100% CNT100 ;
 124:J P[65] 100% CNT100 ;
 125:J P[66] 100% CNT100 ;
 126:J P[67] 100% CNT100 ;
 127:J P[68] 100% CNT100 ;
 128:J P[69] 100% CNT100 ;
 129:J P[70] 100% CNT100 ;
 130:J P[71] 100% CNT100 ;
 131:J P[72] 100% CNT100 ;
 132:J P[73] 100% CNT100 ;
 133:J P[74] 100% CNT100 ;
 134:J P[75] 100% CNT100 ;
 135:J P[76] 100% CNT100 ;
 136:J P[77] 100% CNT100 ;
 137:J P[78] 100% CNT100 ;
 138:J P[79] 100% CNT100 ;
 139:J P[80] 100% CNT100 ;
 140:J P[81] 100% CNT100 ;
 141:J P[82] 100% CNT100 ;
 142:J P[83] 100% CNT100 ;
 143:J P[84] 100% CNT100 ;
 144:J P[85] 100% CNT100 ;
 145:J P[86] 100% CNT100 ;
 146:J P[87] 100% CNT100 ;
 147:J P[88] 100% FINE ;
 148:  !gripper open ;
 149:  DO[1:grip]=OFF ;
 150:  $WAITTMOUT=200 ;
 151:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[4] ;
 152:  WAIT 0.20(sec) ;
 153:L P[89] 263mm/sec FINE ;
 154:J P[90] 100% FINE ;
 155:  !task 4: screw_1 ;
 156:J P[91] 100% FINE ;
 157:L P[92] 175mm/sec FINE ;
 158:  !gripper close ;
 159:  DO[1:grip]=ON ;
 160:  $WAITTMOUT=200 ;
 161:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[5] ;
 162:  WAIT 0.20(sec) ;
 163:J P[93] 100% CNT100 ;
 164:J P[94] 100% CNT100 ;
 165:J P[95] 100% CNT100 ;
 166:J P[96] 100% CNT100 ;
 167:J P[97] 100% CNT100 ;
 168:J P[98] 100% CNT100 ;
 169:J P[99] 100% CNT100 ;
 170:J P[100] 100% CNT100 ;
 171:J P[101] 100% CNT100 ;
 172:J P[102] 100% CNT100 ;
 173:J P[103] 100% CNT100 ;
 174:J P[104] 100% CNT100 ;
 175:J P[105] 100% CNT100 ;
 176:J P[106] 100% CNT100 ;
 177:J P[107] 100% CNT100 ;
 178:J P[108] 100% CNT100 ;
 179:J P[109] 100% CNT100 ;
 180:J P[110] 100% CNT100 ;
 181:J P[111] 100% CNT100 ;
 182:J P[112] 100% CNT100 ;
 183:J P[113] 100% CNT100 ;
 184:J P[114] 100% FINE ;
 185:  !gripper open ;
 186:  DO[1:grip]=OFF ;
 187:  $WAITTMOUT=200 ;
 188:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[6] ;
 189:  WAIT 0.20(sec) ;
 190:L P[115] 263mm/sec FINE ;
 191:J P[116] 100% FINE ;
 192:  !SYNC sync3: ;
 193:  !assembly_MZ07,assembly_MZ07_B ;
 194:  WAIT DI[10:sync_a_in]=OFF ;
 195:  DO[10:sync_a]=ON ;
 196:  WAIT DI[10:sync_a_in]=ON ;
 197:  DO[10:sync_a]=OFF ;
 198:  !SYNC sync4: ;
 199:  !assembly_MZ07_B,assembly_MZ07 ;
 200:  WAIT DI[10:sync_a_in]=OFF ;
 201:  DO[10:sync_a]=ON ;
 202:  WAIT DI[10:sync_a_in]=ON ;
 203:  DO[10:sync_a]=OFF ;
 204:  !task 7: screw_4 ;
 205:J P[117] 100% FINE ;
 206:L P[118] 169mm/sec FINE ;
 207:  !gripper close ;
 208:  DO[1:grip]=ON ;
 209:  $WAITTMOUT=200 ;
 210:  WAIT DI[1:gripper_closed]=ON TIMEOUT,LBL[7] ;
 211:  WAIT 0.20(sec) ;
 212:J P[119] 100% CNT100 ;
 213:J P[120] 100% CNT100 ;
 214:J P[121] 100% CNT100 ;
 215:J P[122] 100% CNT100 ;
 216:J P[123] 100% CNT100 ;
 217:J P[124] 100% CNT100 ;
 218:J P[125] 100% CNT100 ;
 219:J P[126] 100% CNT100 ;
 220:J P[127] 100% CNT100 ;
 221:J P[128] 100% CNT100 ;
 222:J P[129] 100% CNT100 ;
 223:J P[130] 100% CNT100 ;
 224:J P[131] 100% CNT100 ;
 225:J P[132] 100% CNT100 ;
 226:J P[133] 100% CNT100 ;
 227:J P[134] 100% CNT100 ;
 228:J P[135] 100% CNT100 ;
 229:J P[136] 100% CNT100 ;
 230:J P[137] 100% CNT100 ;
 231:J P[138] 100% CNT100 ;
 232:J P[139] 100% CNT100 ;
 233:J P[140] 100% CNT100 ;
 234:J P[141] 100% CNT100 ;
 235:J P[142] 100% CNT100 ;
 236:J P[143] 100% CNT100 ;
 237:J P[144] 100% CNT100 ;
 238:J P[145] 100% CNT100 ;
 239:J P[146] 100% CNT100 ;
 240:J P[147] 100% CNT100 ;
 241:J P[148] 100% CNT100 ;
 242:J P[149] 100% CNT100 ;
 243:J P[150] 100% CNT100 ;
 244:J P[151] 100% CNT100 ;
 245:J P[152] 100% CNT100 ;
 246:J P[153] 100% CNT100 ;
 247:J P[154] 100% CNT100 ;
 248:J P[155] 100% CNT100 ;
 249:J P[156] 100% CNT100 ;
 250:J P[157] 100% CNT100 ;
 251:J P[158] 100% CNT100 ;
 252:J P[159] 100% CNT100 ;
 253:J P[160] 100% FINE ;
 254:  !gripper open ;
 255:  DO[1:grip]=OFF ;
 256:  $WAITTMOUT=200 ;
 257:  WAIT DI[2:gripper_opened]=ON TIMEOUT,LBL[8] ;
 258:  WAIT 0.20(sec) ;
 259:L P[161] 190mm/sec FINE ;
 260:J P[162] 100% FINE ;
 261:  END ;
 262:  LBL[1] ;
 263:  !timeout DI[1] 2 s ;
 264:  MESSAGE[TIMEOUT DI 1] ;
 265:  ABORT ;
 266:  LBL[2] ;
 267:  !timeout DI[2] 2 s ;
 268:  MESSAGE[TIMEOUT DI 2] ;
 269:  ABORT ;
 270:  LBL[3] ;
 271:  !timeout DI[1] 2 s ;
 272:  MESSAGE[TIMEOUT DI 1] ;
 273:  ABORT ;
 274:  LBL[4] ;
 275:  !timeout DI[2] 2 s ;
 276:  MESSAGE[TIMEOUT DI 2] ;
 277:  ABORT ;
 278:  LBL[5] ;
 279:  !timeout DI[1] 2 s ;
 280:  MESSAGE[TIMEOUT DI 1] ;
 281:  ABORT ;
 282:  LBL[6] ;
 283:  !timeout DI[2] 2 s ;
 284:  MESSAGE[TIMEOUT DI 2] ;
 285:  ABORT ;
 286:  LBL[7] ;
 287:  !timeout DI[1] 2 s ;
 288:  MESSAGE[TIMEOUT DI 1] ;
 289:  ABORT ;
 290:  LBL[8] ;
 291:  !timeout DI[2] 2 s ;
 292:  MESSAGE[TIMEOUT DI 2] ;
 293:  ABORT ;
/POS
P[1:"t1_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    270.000000 mm,	Y =    330.000000 mm,	Z =    465.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -60.000000 deg
};
P[2:"t1_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    270.000000 mm,	Y =    330.000000 mm,	Z =    415.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -60.000000 deg
};
P[3:"t1_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    278.250000 mm,	Y =    321.750000 mm,	Z =    413.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -60.750000 deg
};
P[4:"t1_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.500000 mm,	Y =    313.500000 mm,	Z =    412.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -61.500000 deg
};
P[5:"t1_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    294.750000 mm,	Y =    305.250000 mm,	Z =    410.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -62.250000 deg
};
P[6:"t1_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    303.000000 mm,	Y =    297.000000 mm,	Z =    409.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -63.000000 deg
};
P[7:"t1_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    311.250000 mm,	Y =    288.750000 mm,	Z =    408.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -63.750000 deg
};
P[8:"t1_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    319.500000 mm,	Y =    280.500000 mm,	Z =    406.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -64.500000 deg
};
P[9:"t1_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    327.750000 mm,	Y =    272.250000 mm,	Z =    405.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -65.250000 deg
};
P[10:"t1_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    336.000000 mm,	Y =    264.000000 mm,	Z =    404.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -66.000000 deg
};
P[11:"t1_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    344.250000 mm,	Y =    255.750000 mm,	Z =    402.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -66.750000 deg
};
P[12:"t1_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    352.500000 mm,	Y =    247.500000 mm,	Z =    401.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -67.500000 deg
};
P[13:"t1_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    360.750000 mm,	Y =    239.250000 mm,	Z =    400.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -68.250000 deg
};
P[14:"t1_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    369.000000 mm,	Y =    231.000000 mm,	Z =    398.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -69.000000 deg
};
P[15:"t1_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    377.250000 mm,	Y =    222.750000 mm,	Z =    397.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -69.750000 deg
};
P[16:"t1_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    385.500000 mm,	Y =    214.500000 mm,	Z =    396.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -70.500000 deg
};
P[17:"t1_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    393.750000 mm,	Y =    206.250000 mm,	Z =    394.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -71.250000 deg
};
P[18:"t1_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    402.000000 mm,	Y =    198.000000 mm,	Z =    393.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -72.000000 deg
};
P[19:"t1_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    410.250000 mm,	Y =    189.750000 mm,	Z =    392.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -72.750000 deg
};
P[20:"t1_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    418.500000 mm,	Y =    181.500000 mm,	Z =    390.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -73.500000 deg
};
P[21:"t1_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    426.750000 mm,	Y =    173.250000 mm,	Z =    389.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -74.250000 deg
};
P[22:"t1_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    435.000000 mm,	Y =    165.000000 mm,	Z =    388.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.000000 deg
};
P[23:"t1_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    443.250000 mm,	Y =    156.750000 mm,	Z =    386.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.750000 deg
};
P[24:"t1_c22"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    451.500000 mm,	Y =    148.500000 mm,	Z =    385.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -76.500000 deg
};
P[25:"t1_c23"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    459.750000 mm,	Y =    140.250000 mm,	Z =    383.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -77.250000 deg
};
P[26:"t1_c24"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    468.000000 mm,	Y =    132.000000 mm,	Z =    382.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -78.000000 deg
};
P[27:"t1_c25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    476.250000 mm,	Y =    123.750000 mm,	Z =    381.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -78.750000 deg
};
P[28:"t1_c26"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    484.500000 mm,	Y =    115.500000 mm,	Z =    379.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -79.500000 deg
};
P[29:"t1_c27"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    492.750000 mm,	Y =    107.250000 mm,	Z =    378.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -80.250000 deg
};
P[30:"t1_c28"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    501.000000 mm,	Y =     99.000000 mm,	Z =    377.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -81.000000 deg
};
P[31:"t1_c29"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    509.250000 mm,	Y =     90.750000 mm,	Z =    375.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -81.750000 deg
};
P[32:"t1_c30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    517.500000 mm,	Y =     82.500000 mm,	Z =    374.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -82.500000 deg
};
P[33:"t1_c31"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    525.750000 mm,	Y =     74.250000 mm,	Z =    373.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -83.250000 deg
};
P[34:"t1_c32"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    534.000000 mm,	Y =     66.000000 mm,	Z =    371.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -84.000000 deg
};
P[35:"t1_c33"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    542.250000 mm,	Y =     57.750000 mm,	Z =    370.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -84.750000 deg
};
P[36:"t1_c34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.500000 mm,	Y =     49.500000 mm,	Z =    369.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -85.500000 deg
};
P[37:"t1_c35"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    558.750000 mm,	Y =     41.250000 mm,	Z =    367.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -86.250000 deg
};
P[38:"t1_c36"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    567.000000 mm,	Y =     33.000000 mm,	Z =    366.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -87.000000 deg
};
P[39:"t1_c37"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    575.250000 mm,	Y =     24.750000 mm,	Z =    365.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -87.750000 deg
};
P[40:"t1_c38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    583.500000 mm,	Y =     16.500000 mm,	Z =    363.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -88.500000 deg
};
P[41:"t1_c39"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    591.750000 mm,	Y =      8.250000 mm,	Z =    362.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -89.250000 deg
};
P[42:"t1_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =      0.000000 mm,	Z =    361.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[43:"t1_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =      0.000000 mm,	Z =    411.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[44:"t1_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
P[45:"t3_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -200.000000 mm,	Z =    508.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[46:"t3_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -200.000000 mm,	Z =    458.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[47:"t3_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    228.250000 mm,	Y =   -193.125000 mm,	Z =    456.775000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[48:"t3_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    236.500000 mm,	Y =   -186.250000 mm,	Z =    455.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[49:"t3_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    244.750000 mm,	Y =   -179.375000 mm,	Z =    454.325000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[50:"t3_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    253.000000 mm,	Y =   -172.500000 mm,	Z =    453.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[51:"t3_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    261.250000 mm,	Y =   -165.625000 mm,	Z =    451.875000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[52:"t3_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    269.500000 mm,	Y =   -158.750000 mm,	Z =    450.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[53:"t3_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    277.750000 mm,	Y =   -151.875000 mm,	Z =    449.425000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[54:"t3_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.000000 mm,	Y =   -145.000000 mm,	Z =    448.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[55:"t3_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    294.250000 mm,	Y =   -138.125000 mm,	Z =    446.975000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[56:"t3_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    302.500000 mm,	Y =   -131.250000 mm,	Z =    445.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[57:"t3_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    310.750000 mm,	Y =   -124.375000 mm,	Z =    444.525000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[58:"t3_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    319.000000 mm,	Y =   -117.500000 mm,	Z =    443.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[59:"t3_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    327.250000 mm,	Y =   -110.625000 mm,	Z =    442.075000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[60:"t3_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    335.500000 mm,	Y =   -103.750000 mm,	Z =    440.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[61:"t3_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    343.750000 mm,	Y =    -96.875000 mm,	Z =    439.625000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[62:"t3_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    352.000000 mm,	Y =    -90.000000 mm,	Z =    438.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[63:"t3_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    360.250000 mm,	Y =    -83.125000 mm,	Z =    437.175000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[64:"t3_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    368.500000 mm,	Y =    -76.250000 mm,	Z =    435.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[65:"t3_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    376.750000 mm,	Y =    -69.375000 mm,	Z =    434.725000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[66:"t3_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    385.000000 mm,	Y =    -62.500000 mm,	Z =    433.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[67:"t3_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    393.250000 mm,	Y =    -55.625000 mm,	Z =    432.275000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[68:"t3_c22"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    401.500000 mm,	Y =    -48.750000 mm,	Z =    431.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[69:"t3_c23"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    409.750000 mm,	Y =    -41.875000 mm,	Z =    429.825000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[70:"t3_c24"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    418.000000 mm,	Y =    -35.000000 mm,	Z =    428.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[71:"t3_c25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    426.250000 mm,	Y =    -28.125000 mm,	Z =    427.375000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[72:"t3_c26"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    434.500000 mm,	Y =    -21.250000 mm,	Z =    426.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[73:"t3_c27"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    442.750000 mm,	Y =    -14.375000 mm,	Z =    424.925000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[74:"t3_c28"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    451.000000 mm,	Y =     -7.500000 mm,	Z =    423.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[75:"t3_c29"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    459.250000 mm,	Y =     -0.625000 mm,	Z =    422.475000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[76:"t3_c30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    467.500000 mm,	Y =      6.250000 mm,	Z =    421.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[77:"t3_c31"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    475.750000 mm,	Y =     13.125000 mm,	Z =    420.025000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[78:"t3_c32"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    484.000000 mm,	Y =     20.000000 mm,	Z =    418.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[79:"t3_c33"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    492.250000 mm,	Y =     26.875000 mm,	Z =    417.575000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[80:"t3_c34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    500.500000 mm,	Y =     33.750000 mm,	Z =    416.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[81:"t3_c35"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    508.750000 mm,	Y =     40.625000 mm,	Z =    415.125000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[82:"t3_c36"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    517.000000 mm,	Y =     47.500000 mm,	Z =    413.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[83:"t3_c37"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    525.250000 mm,	Y =     54.375000 mm,	Z =    412.675000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[84:"t3_c38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    533.500000 mm,	Y =     61.250000 mm,	Z =    411.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[85:"t3_c39"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    541.750000 mm,	Y =     68.125000 mm,	Z =    410.225000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[86:"t3_c40"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    409.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[87:"t3_c41"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[88:"t3_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    378.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[89:"t3_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =     75.000000 mm,	Z =    428.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[90:"t3_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
P[91:"t4_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -260.000000 mm,	Z =    508.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.000000 deg
};
P[92:"t4_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -260.000000 mm,	Z =    458.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.000000 deg
};
P[93:"t4_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    236.500000 mm,	Y =   -250.750000 mm,	Z =    455.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.750000 deg
};
P[94:"t4_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    253.000000 mm,	Y =   -241.500000 mm,	Z =    453.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -76.500000 deg
};
P[95:"t4_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    269.500000 mm,	Y =   -232.250000 mm,	Z =    450.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -77.250000 deg
};
P[96:"t4_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.000000 mm,	Y =   -223.000000 mm,	Z =    448.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -78.000000 deg
};
P[97:"t4_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    302.500000 mm,	Y =   -213.750000 mm,	Z =    445.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -78.750000 deg
};
P[98:"t4_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    319.000000 mm,	Y =   -204.500000 mm,	Z =    443.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -79.500000 deg
};
P[99:"t4_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    335.500000 mm,	Y =   -195.250000 mm,	Z =    440.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -80.250000 deg
};
P[100:"t4_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    352.000000 mm,	Y =   -186.000000 mm,	Z =    438.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -81.000000 deg
};
P[101:"t4_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    368.500000 mm,	Y =   -176.750000 mm,	Z =    435.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -81.750000 deg
};
P[102:"t4_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    385.000000 mm,	Y =   -167.500000 mm,	Z =    433.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -82.500000 deg
};
P[103:"t4_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    401.500000 mm,	Y =   -158.250000 mm,	Z =    431.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -83.250000 deg
};
P[104:"t4_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    418.000000 mm,	Y =   -149.000000 mm,	Z =    428.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -84.000000 deg
};
P[105:"t4_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    434.500000 mm,	Y =   -139.750000 mm,	Z =    426.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -84.750000 deg
};
P[106:"t4_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    451.000000 mm,	Y =   -130.500000 mm,	Z =    423.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -85.500000 deg
};
P[107:"t4_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    467.500000 mm,	Y =   -121.250000 mm,	Z =    421.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -86.250000 deg
};
P[108:"t4_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    484.000000 mm,	Y =   -112.000000 mm,	Z =    418.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -87.000000 deg
};
P[109:"t4_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    500.500000 mm,	Y =   -102.750000 mm,	Z =    416.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -87.750000 deg
};
P[110:"t4_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    517.000000 mm,	Y =    -93.500000 mm,	Z =    413.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -88.500000 deg
};
P[111:"t4_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    533.500000 mm,	Y =    -84.250000 mm,	Z =    411.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -89.250000 deg
};
P[112:"t4_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    409.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[113:"t4_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[114:"t4_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    378.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[115:"t4_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    550.000000 mm,	Y =    -75.000000 mm,	Z =    428.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[116:"t4_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
P[117:"t7_approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -140.000000 mm,	Z =    508.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -30.000000 deg
};
P[118:"t7_pick"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    220.000000 mm,	Y =   -140.000000 mm,	Z =    458.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -30.000000 deg
};
P[119:"t7_c1"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    229.500000 mm,	Y =   -135.875000 mm,	Z =    456.775000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -31.500000 deg
};
P[120:"t7_c2"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    239.000000 mm,	Y =   -131.750000 mm,	Z =    455.550000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -33.000000 deg
};
P[121:"t7_c3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    248.500000 mm,	Y =   -127.625000 mm,	Z =    454.325000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -34.500000 deg
};
P[122:"t7_c4"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    258.000000 mm,	Y =   -123.500000 mm,	Z =    453.100000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -36.000000 deg
};
P[123:"t7_c5"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    267.500000 mm,	Y =   -119.375000 mm,	Z =    451.875000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -37.500000 deg
};
P[124:"t7_c6"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    277.000000 mm,	Y =   -115.250000 mm,	Z =    450.650000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -39.000000 deg
};
P[125:"t7_c7"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    286.500000 mm,	Y =   -111.125000 mm,	Z =    449.425000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -40.500000 deg
};
P[126:"t7_c8"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    296.000000 mm,	Y =   -107.000000 mm,	Z =    448.200000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -42.000000 deg
};
P[127:"t7_c9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    305.500000 mm,	Y =   -102.875000 mm,	Z =    446.975000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -43.500000 deg
};
P[128:"t7_c10"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    315.000000 mm,	Y =    -98.750000 mm,	Z =    445.750000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -45.000000 deg
};
P[129:"t7_c11"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    324.500000 mm,	Y =    -94.625000 mm,	Z =    444.525000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -46.500000 deg
};
P[130:"t7_c12"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    334.000000 mm,	Y =    -90.500000 mm,	Z =    443.300000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -48.000000 deg
};
P[131:"t7_c13"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    343.500000 mm,	Y =    -86.375000 mm,	Z =    442.075000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -49.500000 deg
};
P[132:"t7_c14"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    353.000000 mm,	Y =    -82.250000 mm,	Z =    440.850000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -51.000000 deg
};
P[133:"t7_c15"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    362.500000 mm,	Y =    -78.125000 mm,	Z =    439.625000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -52.500000 deg
};
P[134:"t7_c16"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    372.000000 mm,	Y =    -74.000000 mm,	Z =    438.400000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -54.000000 deg
};
P[135:"t7_c17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    381.500000 mm,	Y =    -69.875000 mm,	Z =    437.175000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -55.500000 deg
};
P[136:"t7_c18"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    391.000000 mm,	Y =    -65.750000 mm,	Z =    435.950000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -57.000000 deg
};
P[137:"t7_c19"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    400.500000 mm,	Y =    -61.625000 mm,	Z =    434.725000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -58.500000 deg
};
P[138:"t7_c20"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    410.000000 mm,	Y =    -57.500000 mm,	Z =    433.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -60.000000 deg
};
P[139:"t7_c21"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    419.500000 mm,	Y =    -53.375000 mm,	Z =    432.275000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -61.500000 deg
};
P[140:"t7_c22"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    429.000000 mm,	Y =    -49.250000 mm,	Z =    431.050000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -63.000000 deg
};
P[141:"t7_c23"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    438.500000 mm,	Y =    -45.125000 mm,	Z =    429.825000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -64.500000 deg
};
P[142:"t7_c24"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    448.000000 mm,	Y =    -41.000000 mm,	Z =    428.600000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -66.000000 deg
};
P[143:"t7_c25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    457.500000 mm,	Y =    -36.875000 mm,	Z =    427.375000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -67.500000 deg
};
P[144:"t7_c26"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    467.000000 mm,	Y =    -32.750000 mm,	Z =    426.150000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -69.000000 deg
};
P[145:"t7_c27"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    476.500000 mm,	Y =    -28.625000 mm,	Z =    424.925000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -70.500000 deg
};
P[146:"t7_c28"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    486.000000 mm,	Y =    -24.500000 mm,	Z =    423.700000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -72.000000 deg
};
P[147:"t7_c29"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    495.500000 mm,	Y =    -20.375000 mm,	Z =    422.475000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -73.500000 deg
};
P[148:"t7_c30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    505.000000 mm,	Y =    -16.250000 mm,	Z =    421.250000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -75.000000 deg
};
P[149:"t7_c31"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    514.500000 mm,	Y =    -12.125000 mm,	Z =    420.025000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -76.500000 deg
};
P[150:"t7_c32"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    524.000000 mm,	Y =     -8.000000 mm,	Z =    418.800000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -78.000000 deg
};
P[151:"t7_c33"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    533.500000 mm,	Y =     -3.875000 mm,	Z =    417.575000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -79.500000 deg
};
P[152:"t7_c34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    543.000000 mm,	Y =      0.250000 mm,	Z =    416.350000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -81.000000 deg
};
P[153:"t7_c35"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    552.500000 mm,	Y =      4.375000 mm,	Z =    415.125000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -82.500000 deg
};
P[154:"t7_c36"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    562.000000 mm,	Y =      8.500000 mm,	Z =    413.900000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -84.000000 deg
};
P[155:"t7_c37"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    571.500000 mm,	Y =     12.625000 mm,	Z =    412.675000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -85.500000 deg
};
P[156:"t7_c38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    581.000000 mm,	Y =     16.750000 mm,	Z =    411.450000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -87.000000 deg
};
P[157:"t7_c39"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    590.500000 mm,	Y =     20.875000 mm,	Z =    410.225000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -88.500000 deg
};
P[158:"t7_c40"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =     25.000000 mm,	Z =    409.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[159:"t7_c41"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =     25.000000 mm,	Z =    393.500000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[160:"t7_place"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =     25.000000 mm,	Z =    378.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[161:"t7_retreat"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    600.000000 mm,	Y =     25.000000 mm,	Z =    428.000000 mm,
	W =    180.000000 deg,	P =      0.000000 deg,	R =    -90.000000 deg
};
P[162:"t7_home"]{
   GP1:
	UF : 1, UT : 1,
	J1=      0.000000 deg,	J2=    110.000000 deg,	J3=      0.000000 deg,
	J4=      0.000000 deg,	J5=      0.000000 deg,	J6=      0.000000 deg
};
/END
