/PROG  POLISH
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 438;
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
   1:  !note: NO FORCE CONTROL: ;
   2:  !position-only targets D = F/k = ;
   3:  !4.000 mm inside the surface ;
   4:  !(along the tool axis), they ;
   5:  !assume a compliant tool of ;
   6:  !spring rate k = 5000 N/m that ;
   7:  !presses with F = 20 N there, a ;
   8:  !stiffer tool presses harder, a ;
   9:  !rigid one is driven 4.000 mm ;
  10:  !into the part ;
  11:  !note: renamed ;
  12:  !'polishing_spindle' to ;
  13:  !'polishing_spindl': FANUC LS ;
  14:  !names have at most 16 characters ;
  15:  !note: TCP speed rounded to the ;
  16:  !controller's steps on 373 lines, ;
  17:  !the largest: program polish, ;
  18:  !move 1 (p3): TCP speed 40.7236 ;
  19:  !mm/s written as 40.6667 mm/s ;
  20:  !note: zone rounded to the ;
  21:  !controller's steps on 64 lines, ;
  22:  !the largest: program polish, ;
  23:  !move 15 (p76): zone 0.1 mm ;
  24:  !written as 1 mm ;
  25:  !workbench program polish ;
  26:  !frames (set below from PR): ;
  27:  !UTOOL[1]: polishing_spindl ;
  28:  !UT1 mass 3.500 kg ;
  29:  !UT1 cog 0.0,0.0,75.0 mm ;
  30:  !UFRAME[1]: workpiece ;
  31:  PR[90]=LPOS-LPOS ;
  32:  PR[90,1]=0.000000 ;
  33:  PR[90,2]=0.000000 ;
  34:  PR[90,3]=150.000000 ;
  35:  PR[90,4]=0.000000 ;
  36:  PR[90,5]=0.000000 ;
  37:  PR[90,6]=0.000000 ;
  38:  UTOOL[1]=PR[90] ;
  39:  PR[90]=LPOS-LPOS ;
  40:  PR[90,1]=480.000000 ;
  41:  PR[90,2]=0.000000 ;
  42:  PR[90,3]=340.000000 ;
  43:  PR[90,4]=0.000000 ;
  44:  PR[90,5]=0.000000 ;
  45:  PR[90,6]=90.000000 ;
  46:  UFRAME[1]=PR[90] ;
  47:  !polishing: contact force F = 20 ;
  48:  !N through the contact stiffness ;
  49:  !k = 5000 N/m: process targets ;
  50:  !offset D = F/k = 4.000 mm into ;
  51:  !the surface along the tool axis ;
  52:  !path: 1221 planned points as 373 ;
  53:  !linear moves within 0.05 mm ;
  54:  !(chord) and 0.5 deg (tool axis), ;
  55:  !feed 40 mm/s ;
  56:  !TCP speed 40.72 mm/s: the feed ;
  57:  !40 mm/s, scaled so that the ;
  58:  !moves take the planned 95.24 s ;
  59:  UTOOL_NUM=1 ;
  60:  UFRAME_NUM=1 ;
  61:J P[1] 10% FINE ;
  62:  !process: press with F = 20 N ;
  63:  !(offset D = 4.000 mm) ;
  64:L P[2] 244cm/min FINE ;
  65:L P[3] 244cm/min CR2 ;
  66:L P[4] 244cm/min CR2 ;
  67:L P[5] 244cm/min CR2 ;
  68:L P[6] 244cm/min CR2 ;
  69:L P[7] 244cm/min CR2 ;
  70:L P[8] 244cm/min CR2 ;
  71:L P[9] 244cm/min CR2 ;
  72:L P[10] 244cm/min CR2 ;
  73:L P[11] 244cm/min CR2 ;
  74:L P[12] 244cm/min CR2 ;
  75:L P[13] 244cm/min CR2 ;
  76:L P[14] 244cm/min CR2 ;
  77:L P[15] 244cm/min CR1 ;
  78:L P[16] 244cm/min CR1 ;
  79:L P[17] 244cm/min CR2 ;
  80:L P[18] 244cm/min CR2 ;
  81:L P[19] 244cm/min CR2 ;
  82:L P[20] 244cm/min CR2 ;
  83:L P[21] 244cm/min CR2 ;
  84:L P[22] 244cm/min CR2 ;
  85:L P[23] 244cm/min CR2 ;
  86:L P[24] 244cm/min CR2 ;
  87:L P[25] 244cm/min CR2 ;
  88:L P[26] 244cm/min CR2 ;
  89:L P[27] 244cm/min CR2 ;
  90:L P[28] 244cm/min CR2 ;
  91:L P[29] 244cm/min CR2 ;
  92:L P[30] 244cm/min CR2 ;
  93:L P[31] 244cm/min CR2 ;
  94:L P[32] 244cm/min CR1 ;
  95:L P[33] 244cm/min CR1 ;
  96:L P[34] 244cm/min CR1 ;
  97:L P[35] 244cm/min CR2 ;
  98:L P[36] 244cm/min CR2 ;
  99:L P[37] 244cm/min CR2 ;
 100:L P[38] 244cm/min CR2 ;
 101:L P[39] 244cm/min CR2 ;
 102:L P[40] 244cm/min CR2 ;
 103:L P[41] 244cm/min CR2 ;
 104:L P[42] 244cm/min CR2 ;
 105:L P[43] 244cm/min CR2 ;
 106:L P[44] 244cm/min CR2 ;
 107:L P[45] 244cm/min CR2 ;
 108:L P[46] 244cm/min CR2 ;
 109:L P[47] 244cm/min CR2 ;
 110:L P[48] 244cm/min CR2 ;
 111:L P[49] 244cm/min CR2 ;
 112:L P[50] 244cm/min CR2 ;
 113:L P[51] 244cm/min CR2 ;
 114:L P[52] 244cm/min CR1 ;
 115:L P[53] 244cm/min CR1 ;
 116:L P[54] 244cm/min CR2 ;
 117:L P[55] 244cm/min CR2 ;
 118:L P[56] 244cm/min CR2 ;
 119:L P[57] 244cm/min CR2 ;
 120:L P[58] 244cm/min CR2 ;
 121:L P[59] 244cm/min CR2 ;
 122:L P[60] 244cm/min CR2 ;
 123:L P[61] 244cm/min CR2 ;
 124:L P[62] 244cm/min CR2 ;
 125:L P[63] 244cm/min CR2 ;
 126:L P[64] 244cm/min CR2 ;
 127:L P[65] 244cm/min CR2 ;
 128:L P[66] 244cm/min CR2 ;
 129:L P[67] 244cm/min CR2 ;
 130:L P[68] 244cm/min CR2 ;
 131:L P[69] 244cm/min CR2 ;
 132:L P[70] 244cm/min CR2 ;
 133:L P[71] 244cm/min CR2 ;
 134:L P[72] 244cm/min CR1 ;
 135:L P[73] 244cm/min CR1 ;
 136:L P[74] 244cm/min CR2 ;
 137:L P[75] 244cm/min CR2 ;
 138:L P[76] 244cm/min CR2 ;
 139:L P[77] 244cm/min CR2 ;
 140:L P[78] 244cm/min CR2 ;
 141:L P[79] 244cm/min CR2 ;
 142:L P[80] 244cm/min CR2 ;
 143:L P[81] 244cm/min CR2 ;
 144:L P[82] 244cm/min CR2 ;
 145:L P[83] 244cm/min CR2 ;
 146:L P[84] 244cm/min CR2 ;
 147:L P[85] 244cm/min CR2 ;
 148:L P[86] 244cm/min CR2 ;
 149:L P[87] 244cm/min CR2 ;
 150:L P[88] 244cm/min CR2 ;
 151:L P[89] 244cm/min CR2 ;
 152:L P[90] 244cm/min CR2 ;
 153:L P[91] 244cm/min CR1 ;
 154:L P[92] 244cm/min CR1 ;
 155:L P[93] 244cm/min CR2 ;
 156:L P[94] 244cm/min CR1 ;
 157:L P[95] 244cm/min CR2 ;
 158:L P[96] 244cm/min CR2 ;
 159:L P[97] 244cm/min CR2 ;
 160:L P[98] 244cm/min CR2 ;
 161:L P[99] 244cm/min CR2 ;
 162:L P[100] 244cm/min CR2 ;
 163:L P[101] 244cm/min CR2 ;
 164:L P[102] 244cm/min CR2 ;
 165:L P[103] 244cm/min CR2 ;
 166:L P[104] 244cm/min CR2 ;
 167:L P[105] 244cm/min CR2 ;
 168:L P[106] 244cm/min CR1 ;
 169:L P[107] 244cm/min CR1 ;
 170:L P[108] 244cm/min CR1 ;
 171:L P[109] 244cm/min CR2 ;
 172:L P[110] 244cm/min CR2 ;
 173:L P[111] 244cm/min CR2 ;
 174:L P[112] 244cm/min CR2 ;
 175:L P[113] 244cm/min CR2 ;
 176:L P[114] 244cm/min CR2 ;
 177:L P[115] 244cm/min CR2 ;
 178:L P[116] 244cm/min CR2 ;
 179:L P[117] 244cm/min CR2 ;
 180:L P[118] 244cm/min CR2 ;
 181:L P[119] 244cm/min CR2 ;
 182:L P[120] 244cm/min CR2 ;
 183:L P[121] 244cm/min CR2 ;
 184:L P[122] 244cm/min CR2 ;
 185:L P[123] 244cm/min CR2 ;
 186:L P[124] 244cm/min CR2 ;
 187:L P[125] 244cm/min CR2 ;
 188:L P[126] 244cm/min CR1 ;
 189:L P[127] 244cm/min CR1 ;
 190:L P[128] 244cm/min CR1 ;
 191:L P[129] 244cm/min CR2 ;
 192:L P[130] 244cm/min CR2 ;
 193:L P[131] 244cm/min CR2 ;
 194:L P[132] 244cm/min CR2 ;
 195:L P[133] 244cm/min CR2 ;
 196:L P[134] 244cm/min CR2 ;
 197:L P[135] 244cm/min CR2 ;
 198:L P[136] 244cm/min CR2 ;
 199:L P[137] 244cm/min CR2 ;
 200:L P[138] 244cm/min CR2 ;
 201:L P[139] 244cm/min CR2 ;
 202:L P[140] 244cm/min CR2 ;
 203:L P[141] 244cm/min CR2 ;
 204:L P[142] 244cm/min CR2 ;
 205:L P[143] 244cm/min CR2 ;
 206:L P[144] 244cm/min CR1 ;
 207:L P[145] 244cm/min CR1 ;
 208:L P[146] 244cm/min CR2 ;
 209:L P[147] 244cm/min CR2 ;
 210:L P[148] 244cm/min CR2 ;
 211:L P[149] 244cm/min CR2 ;
 212:L P[150] 244cm/min CR2 ;
 213:L P[151] 244cm/min CR2 ;
 214:L P[152] 244cm/min CR2 ;
 215:L P[153] 244cm/min CR2 ;
 216:L P[154] 244cm/min CR2 ;
 217:L P[155] 244cm/min CR2 ;
 218:L P[156] 244cm/min CR2 ;
 219:L P[157] 244cm/min CR2 ;
 220:L P[158] 244cm/min CR2 ;
 221:L P[159] 244cm/min CR2 ;
 222:L P[160] 244cm/min CR2 ;
 223:L P[161] 244cm/min CR2 ;
 224:L P[162] 244cm/min CR2 ;
 225:L P[163] 244cm/min CR1 ;
 226:L P[164] 244cm/min CR1 ;
 227:L P[165] 244cm/min CR1 ;
 228:L P[166] 244cm/min CR1 ;
 229:L P[167] 244cm/min CR2 ;
 230:L P[168] 244cm/min CR2 ;
 231:L P[169] 244cm/min CR2 ;
 232:L P[170] 244cm/min CR2 ;
 233:L P[171] 244cm/min CR2 ;
 234:L P[172] 244cm/min CR2 ;
 235:L P[173] 244cm/min CR1 ;
 236:L P[174] 244cm/min CR1 ;
 237:L P[175] 244cm/min CR1 ;
 238:L P[176] 244cm/min CR1 ;
 239:L P[177] 244cm/min CR2 ;
 240:L P[178] 244cm/min CR2 ;
 241:L P[179] 244cm/min CR2 ;
 242:L P[180] 244cm/min CR2 ;
 243:L P[181] 244cm/min CR2 ;
 244:L P[182] 244cm/min CR2 ;
 245:L P[183] 244cm/min CR2 ;
 246:L P[184] 244cm/min CR2 ;
 247:L P[185] 244cm/min CR2 ;
 248:L P[186] 244cm/min CR2 ;
 249:L P[187] 244cm/min CR2 ;
 250:L P[188] 244cm/min CR2 ;
 251:L P[189] 244cm/min CR2 ;
 252:L P[190] 244cm/min CR2 ;
 253:L P[191] 244cm/min CR2 ;
 254:L P[192] 244cm/min CR2 ;
 255:L P[193] 244cm/min CR1 ;
 256:L P[194] 244cm/min CR1 ;
 257:L P[195] 244cm/min CR1 ;
 258:L P[196] 244cm/min CR1 ;
 259:L P[197] 244cm/min CR2 ;
 260:L P[198] 244cm/min CR2 ;
 261:L P[199] 244cm/min CR2 ;
 262:L P[200] 244cm/min CR2 ;
 263:L P[201] 244cm/min CR2 ;
 264:L P[202] 244cm/min CR2 ;
 265:L P[203] 244cm/min CR2 ;
 266:L P[204] 244cm/min CR2 ;
 267:L P[205] 244cm/min CR2 ;
 268:L P[206] 244cm/min CR2 ;
 269:L P[207] 244cm/min CR2 ;
 270:L P[208] 244cm/min CR1 ;
 271:L P[209] 244cm/min CR1 ;
 272:L P[210] 244cm/min CR2 ;
 273:L P[211] 244cm/min CR2 ;
 274:L P[212] 244cm/min CR2 ;
 275:L P[213] 244cm/min CR2 ;
 276:L P[214] 244cm/min CR2 ;
 277:L P[215] 244cm/min CR2 ;
 278:L P[216] 244cm/min CR2 ;
 279:L P[217] 244cm/min CR2 ;
 280:L P[218] 244cm/min CR2 ;
 281:L P[219] 244cm/min CR2 ;
 282:L P[220] 244cm/min CR2 ;
 283:L P[221] 244cm/min CR2 ;
 284:L P[222] 244cm/min CR2 ;
 285:L P[223] 244cm/min CR2 ;
 286:L P[224] 244cm/min CR2 ;
 287:L P[225] 244cm/min CR2 ;
 288:L P[226] 244cm/min CR2 ;
 289:L P[227] 244cm/min CR2 ;
 290:L P[228] 244cm/min CR1 ;
 291:L P[229] 244cm/min CR2 ;
 292:L P[230] 244cm/min CR1 ;
 293:L P[231] 244cm/min CR1 ;
 294:L P[232] 244cm/min CR2 ;
 295:L P[233] 244cm/min CR2 ;
 296:L P[234] 244cm/min CR2 ;
 297:L P[235] 244cm/min CR2 ;
 298:L P[236] 244cm/min CR1 ;
 299:L P[237] 244cm/min CR1 ;
 300:L P[238] 244cm/min CR1 ;
 301:L P[239] 244cm/min CR2 ;
 302:L P[240] 244cm/min CR2 ;
 303:L P[241] 244cm/min CR2 ;
 304:L P[242] 244cm/min CR2 ;
 305:L P[243] 244cm/min CR2 ;
 306:L P[244] 244cm/min CR2 ;
 307:L P[245] 244cm/min CR2 ;
 308:L P[246] 244cm/min CR2 ;
 309:L P[247] 244cm/min CR2 ;
 310:L P[248] 244cm/min CR2 ;
 311:L P[249] 244cm/min CR2 ;
 312:L P[250] 244cm/min CR2 ;
 313:L P[251] 244cm/min CR2 ;
 314:L P[252] 244cm/min CR2 ;
 315:L P[253] 244cm/min CR2 ;
 316:L P[254] 244cm/min CR2 ;
 317:L P[255] 244cm/min CR2 ;
 318:L P[256] 244cm/min CR2 ;
 319:L P[257] 244cm/min CR1 ;
 320:L P[258] 244cm/min CR1 ;
 321:L P[259] 244cm/min CR1 ;
 322:L P[260] 244cm/min CR1 ;
 323:L P[261] 244cm/min CR2 ;
 324:L P[262] 244cm/min CR2 ;
 325:L P[263] 244cm/min CR2 ;
 326:L P[264] 244cm/min CR2 ;
 327:L P[265] 244cm/min CR2 ;
 328:L P[266] 244cm/min CR2 ;
 329:L P[267] 244cm/min CR1 ;
 330:L P[268] 244cm/min CR1 ;
 331:L P[269] 244cm/min CR2 ;
 332:L P[270] 244cm/min CR2 ;
 333:L P[271] 244cm/min CR2 ;
 334:L P[272] 244cm/min CR2 ;
 335:L P[273] 244cm/min CR2 ;
 336:L P[274] 244cm/min CR2 ;
 337:L P[275] 244cm/min CR2 ;
 338:L P[276] 244cm/min CR2 ;
 339:L P[277] 244cm/min CR2 ;
 340:L P[278] 244cm/min CR2 ;
 341:L P[279] 244cm/min CR2 ;
 342:L P[280] 244cm/min CR2 ;
 343:L P[281] 244cm/min CR2 ;
 344:L P[282] 244cm/min CR2 ;
 345:L P[283] 244cm/min CR2 ;
 346:L P[284] 244cm/min CR2 ;
 347:L P[285] 244cm/min CR2 ;
 348:L P[286] 244cm/min CR1 ;
 349:L P[287] 244cm/min CR2 ;
 350:L P[288] 244cm/min CR1 ;
 351:L P[289] 244cm/min CR1 ;
 352:L P[290] 244cm/min CR2 ;
 353:L P[291] 244cm/min CR1 ;
 354:L P[292] 244cm/min CR1 ;
 355:L P[293] 244cm/min CR2 ;
 356:L P[294] 244cm/min CR1 ;
 357:L P[295] 244cm/min CR2 ;
 358:L P[296] 244cm/min CR2 ;
 359:L P[297] 244cm/min CR2 ;
 360:L P[298] 244cm/min CR2 ;
 361:L P[299] 244cm/min CR2 ;
 362:L P[300] 244cm/min CR2 ;
 363:L P[301] 244cm/min CR2 ;
 364:L P[302] 244cm/min CR2 ;
 365:L P[303] 244cm/min CR2 ;
 366:L P[304] 244cm/min CR2 ;
 367:L P[305] 244cm/min CR2 ;
 368:L P[306] 244cm/min CR2 ;
 369:L P[307] 244cm/min CR2 ;
 370:L P[308] 244cm/min CR2 ;
 371:L P[309] 244cm/min CR1 ;
 372:L P[310] 244cm/min CR1 ;
 373:L P[311] 244cm/min CR1 ;
 374:L P[312] 244cm/min CR2 ;
 375:L P[313] 244cm/min FINE ;
 376:L P[314] 244cm/min FINE ;
 377:L P[315] 244cm/min CR2 ;
 378:L P[316] 244cm/min CR2 ;
 379:L P[317] 244cm/min CR2 ;
 380:L P[318] 244cm/min CR2 ;
 381:L P[319] 244cm/min CR2 ;
 382:L P[320] 244cm/min CR2 ;
 383:L P[321] 244cm/min CR2 ;
 384:L P[322] 244cm/min CR2 ;
 385:L P[323] 244cm/min CR2 ;
 386:L P[324] 244cm/min CR2 ;
 387:L P[325] 244cm/min CR2 ;
 388:L P[326] 244cm/min CR2 ;
 389:L P[327] 244cm/min CR2 ;
 390:L P[328] 244cm/min CR1 ;
 391:L P[329] 244cm/min CR1 ;
 392:L P[330] 244cm/min CR1 ;
 393:L P[331] 244cm/min CR1 ;
 394:L P[332] 244cm/min CR1 ;
 395:L P[333] 244cm/min CR1 ;
 396:L P[334] 244cm/min CR1 ;
 397:L P[335] 244cm/min CR2 ;
 398:L P[336] 244cm/min CR2 ;
 399:L P[337] 244cm/min CR2 ;
 400:L P[338] 244cm/min CR2 ;
 401:L P[339] 244cm/min CR2 ;
 402:L P[340] 244cm/min CR2 ;
 403:L P[341] 244cm/min CR2 ;
 404:L P[342] 244cm/min CR2 ;
 405:L P[343] 244cm/min CR2 ;
 406:L P[344] 244cm/min CR2 ;
 407:L P[345] 244cm/min CR2 ;
 408:L P[346] 244cm/min CR1 ;
 409:L P[347] 244cm/min CR1 ;
 410:L P[348] 244cm/min CR1 ;
 411:L P[349] 244cm/min CR2 ;
 412:L P[350] 244cm/min CR2 ;
 413:L P[351] 244cm/min CR2 ;
 414:L P[352] 244cm/min CR2 ;
 415:L P[353] 244cm/min CR2 ;
 416:L P[354] 244cm/min CR2 ;
 417:L P[355] 244cm/min CR2 ;
 418:L P[356] 244cm/min CR2 ;
 419:L P[357] 244cm/min CR2 ;
 420:L P[358] 244cm/min CR2 ;
 421:L P[359] 244cm/min CR2 ;
 422:L P[360] 244cm/min CR1 ;
 423:L P[361] 244cm/min CR1 ;
 424:L P[362] 244cm/min CR1 ;
 425:L P[363] 244cm/min CR1 ;
 426:L P[364] 244cm/min CR2 ;
 427:L P[365] 244cm/min CR2 ;
 428:L P[366] 244cm/min CR2 ;
 429:L P[367] 244cm/min CR2 ;
 430:L P[368] 244cm/min CR2 ;
 431:L P[369] 244cm/min CR2 ;
 432:L P[370] 244cm/min CR2 ;
 433:L P[371] 244cm/min CR2 ;
 434:L P[372] 244cm/min CR2 ;
 435:L P[373] 244cm/min CR1 ;
 436:  !lead-out: off the surface, no ;
 437:  !contact force ;
 438:L P[374] 244cm/min FINE ;
/POS
P[1:"approach"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -79.206077 mm,	Y =    -95.098784 mm,	Z =     34.027266 mm,
	W =   -166.060619 deg,	P =     -4.894772 deg,	R =     -1.213246 deg
};
P[2:"p3"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -77.096590 mm,	Y =    -89.360678 mm,	Z =     10.818987 mm,
	W =   -166.060619 deg,	P =     -4.894772 deg,	R =     -1.213246 deg
};
P[3:"p9"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -59.236238 mm,	Y =    -89.437965 mm,	Z =     12.207983 mm,
	W =   -168.498408 deg,	P =     -3.787624 deg,	R =     -0.770103 deg
};
P[4:"p17"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -35.333362 mm,	Y =    -89.489300 mm,	Z =     13.662470 mm,
	W =   -169.858670 deg,	P =     -3.077590 deg,	R =     -0.550211 deg
};
P[5:"p25"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -11.423546 mm,	Y =    -89.448369 mm,	Z =     14.839097 mm,
	W =   -168.033477 deg,	P =     -2.190043 deg,	R =     -0.464048 deg
};
P[6:"p30"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      3.490531 mm,	Y =    -89.400187 mm,	Z =     15.308381 mm,
	W =   -165.972184 deg,	P =     -1.075069 deg,	R =     -0.268581 deg
};
P[7:"p34"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     15.400170 mm,	Y =    -89.355355 mm,	Z =     15.425948 mm,
	W =   -164.438546 deg,	P =      0.168024 deg,	R =      0.046791 deg
};
P[8:"p38"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     27.292764 mm,	Y =    -89.328743 mm,	Z =     15.235306 mm,
	W =   -163.405576 deg,	P =      1.610118 deg,	R =      0.479752 deg
};
P[9:"p42"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     39.163400 mm,	Y =    -89.323567 mm,	Z =     14.692402 mm,
	W =   -163.108252 deg,	P =      3.201950 deg,	R =      0.971724 deg
};
P[10:"p46"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     51.015044 mm,	Y =    -89.328902 mm,	Z =     13.788888 mm,
	W =   -163.596045 deg,	P =      4.781914 deg,	R =      1.405837 deg
};
P[11:"p50"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     62.850886 mm,	Y =    -89.347011 mm,	Z =     12.548620 mm,
	W =   -164.785331 deg,	P =      6.209991 deg,	R =      1.685134 deg
};
P[12:"p55"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     77.625087 mm,	Y =    -89.394441 mm,	Z =     10.606677 mm,
	W =   -166.781487 deg,	P =      7.694495 deg,	R =      1.801329 deg
};
P[13:"p62"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     98.302295 mm,	Y =    -89.470342 mm,	Z =      7.412337 mm,
	W =   -169.208699 deg,	P =      8.920979 deg,	R =      1.693009 deg
};
P[14:"p70"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    121.929687 mm,	Y =    -89.492353 mm,	Z =      3.440310 mm,
	W =   -169.438589 deg,	P =      9.511742 deg,	R =      1.764751 deg
};
P[15:"p75"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    136.658104 mm,	Y =    -89.457205 mm,	Z =      0.823655 mm,
	W =   -167.995188 deg,	P =      9.991157 deg,	R =      2.112854 deg
};
P[16:"p76"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.328710 mm,	Y =    -88.090380 mm,	Z =      0.620744 mm,
	W =   -167.844718 deg,	P =      9.946966 deg,	R =      2.130757 deg
};
P[17:"p77"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.502387 mm,	Y =    -85.177802 mm,	Z =      1.196384 mm,
	W =   -168.261770 deg,	P =      9.612760 deg,	R =      1.987242 deg
};
P[18:"p81"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.546849 mm,	Y =    -73.499741 mm,	Z =      3.403464 mm,
	W =   -169.987823 deg,	P =      8.248375 deg,	R =      1.450884 deg
};
P[19:"p85"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.600549 mm,	Y =    -61.761967 mm,	Z =      5.272260 mm,
	W =   -171.677953 deg,	P =      6.939868 deg,	R =      1.012559 deg
};
P[20:"p89"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.656616 mm,	Y =    -49.974345 mm,	Z =      6.806975 mm,
	W =   -173.326918 deg,	P =      5.753288 deg,	R =      0.671954 deg
};
P[21:"p93"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.705666 mm,	Y =    -38.147157 mm,	Z =      8.011660 mm,
	W =   -174.943441 deg,	P =      4.742360 deg,	R =      0.419134 deg
};
P[22:"p97"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.748997 mm,	Y =    -26.290024 mm,	Z =      8.888970 mm,
	W =   -176.534131 deg,	P =      3.959378 deg,	R =      0.239606 deg
};
P[23:"p101"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.777487 mm,	Y =    -14.412428 mm,	Z =      9.441714 mm,
	W =   -178.106418 deg,	P =      3.452573 deg,	R =      0.114077 deg
};
P[24:"p105"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.789557 mm,	Y =     -2.522644 mm,	Z =      9.671394 mm,
	W =   -179.653958 deg,	P =      3.234479 deg,	R =      0.019525 deg
};
P[25:"p109"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.784372 mm,	Y =      9.366940 mm,	Z =      9.578640 mm,
	W =    178.769367 deg,	P =      3.319199 deg,	R =     -0.071263 deg
};
P[26:"p113"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.760014 mm,	Y =     21.250421 mm,	Z =      9.163304 mm,
	W =    177.202489 deg,	P =      3.713384 deg,	R =     -0.181325 deg
};
P[27:"p117"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.720888 mm,	Y =     33.118348 mm,	Z =      8.424111 mm,
	W =    175.634317 deg,	P =      4.383786 deg,	R =     -0.334343 deg
};
P[28:"p121"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.670800 mm,	Y =     44.958531 mm,	Z =      7.359158 mm,
	W =    174.016331 deg,	P =      5.298400 deg,	R =     -0.554549 deg
};
P[29:"p125"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.612370 mm,	Y =     56.764313 mm,	Z =      5.965584 mm,
	W =    172.382958 deg,	P =      6.421988 deg,	R =     -0.856959 deg
};
P[30:"p129"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.554693 mm,	Y =     68.524761 mm,	Z =      4.239620 mm,
	W =    170.713353 deg,	P =      7.687202 deg,	R =     -1.253021 deg
};
P[31:"p133"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.498887 mm,	Y =     80.229727 mm,	Z =      2.178030 mm,
	W =    169.002479 deg,	P =      9.034081 deg,	R =     -1.747834 deg
};
P[32:"p135"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    139.473226 mm,	Y =     86.058261 mm,	Z =      1.020269 mm,
	W =    168.132503 deg,	P =      9.719204 deg,	R =     -2.031767 deg
};
P[33:"p136"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    138.702321 mm,	Y =     88.906981 mm,	Z =      0.562630 mm,
	W =    167.827420 deg,	P =     10.017410 deg,	R =     -2.148823 deg
};
P[34:"p137"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    135.783506 mm,	Y =     89.441724 mm,	Z =      0.987306 mm,
	W =    168.102495 deg,	P =      9.956610 deg,	R =     -2.086269 deg
};
P[35:"p146"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    109.240760 mm,	Y =     89.498838 mm,	Z =      5.601479 mm,
	W =    169.756582 deg,	P =      9.232212 deg,	R =     -1.660685 deg
};
P[36:"p154"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     85.607475 mm,	Y =     89.447274 mm,	Z =      9.417677 mm,
	W =    167.871721 deg,	P =      8.273417 deg,	R =     -1.771202 deg
};
P[37:"p159"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     70.836320 mm,	Y =     89.397909 mm,	Z =     11.538859 mm,
	W =    165.833620 deg,	P =      7.074649 deg,	R =     -1.780637 deg
};
P[38:"p163"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     59.011768 mm,	Y =     89.362351 mm,	Z =     12.978955 mm,
	W =    164.331088 deg,	P =      5.770512 deg,	R =     -1.615477 deg
};
P[39:"p167"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.171766 mm,	Y =     89.338246 mm,	Z =     14.117218 mm,
	W =    163.359445 deg,	P =      4.274851 deg,	R =     -1.276288 deg
};
P[40:"p171"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     35.314244 mm,	Y =     89.322059 mm,	Z =     14.908842 mm,
	W =    163.112211 deg,	P =      2.677866 deg,	R =     -0.812624 deg
};
P[41:"p175"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     23.434668 mm,	Y =     89.316638 mm,	Z =     15.339558 mm,
	W =    163.671627 deg,	P =      1.149197 deg,	R =     -0.336640 deg
};
P[42:"p179"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     11.539078 mm,	Y =     89.330667 mm,	Z =     15.428523 mm,
	W =    164.899979 deg,	P =     -0.273335 deg,	R =      0.073751 deg
};
P[43:"p184"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -3.359254 mm,	Y =     89.390439 mm,	Z =     15.137157 mm,
	W =    166.943203 deg,	P =     -1.655193 deg,	R =      0.383801 deg
};
P[44:"p190"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -21.274881 mm,	Y =     89.458301 mm,	Z =     14.400304 mm,
	W =    169.127398 deg,	P =     -2.654181 deg,	R =      0.509603 deg
};
P[45:"p198"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -45.193434 mm,	Y =     89.485870 mm,	Z =     13.095676 mm,
	W =    169.676495 deg,	P =     -3.308782 deg,	R =      0.602353 deg
};
P[46:"p205"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -66.084908 mm,	Y =     89.433841 mm,	Z =     11.714828 mm,
	W =    167.629379 deg,	P =     -4.134222 deg,	R =      0.905883 deg
};
P[47:"p210"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -80.945806 mm,	Y =     89.388500 mm,	Z =     10.449485 mm,
	W =    165.514181 deg,	P =     -5.233950 deg,	R =      1.350080 deg
};
P[48:"p214"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -92.783265 mm,	Y =     89.358320 mm,	Z =      9.163925 mm,
	W =    164.022744 deg,	P =     -6.433102 deg,	R =      1.837401 deg
};
P[49:"p218"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.569165 mm,	Y =     89.343994 mm,	Z =      7.568976 mm,
	W =    163.116807 deg,	P =     -7.832624 deg,	R =      2.368476 deg
};
P[50:"p222"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -116.297954 mm,	Y =     89.337266 mm,	Z =      5.634513 mm,
	W =    162.943451 deg,	P =     -9.364783 deg,	R =      2.858063 deg
};
P[51:"p226"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -127.971151 mm,	Y =     89.340563 mm,	Z =      3.360225 mm,
	W =    163.532665 deg,	P =    -10.901447 deg,	R =      3.199659 deg
};
P[52:"p229"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -136.693309 mm,	Y =     89.355687 mm,	Z =      1.447931 mm,
	W =    164.433734 deg,	P =    -11.977229 deg,	R =      3.308573 deg
};
P[53:"p230"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.383842 mm,	Y =     88.169863 mm,	Z =      1.139675 mm,
	W =    164.939976 deg,	P =    -12.462518 deg,	R =      3.323208 deg
};
P[54:"p234"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.356469 mm,	Y =     76.635322 mm,	Z =      3.985539 mm,
	W =    166.648566 deg,	P =    -14.054886 deg,	R =      3.298755 deg
};
P[55:"p238"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.331076 mm,	Y =     65.021945 mm,	Z =      6.468556 mm,
	W =    168.457519 deg,	P =    -15.569471 deg,	R =      3.137540 deg
};
P[56:"p242"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.310177 mm,	Y =     53.337634 mm,	Z =      8.570246 mm,
	W =    170.369069 deg,	P =    -16.948395 deg,	R =      2.831951 deg
};
P[57:"p245"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.306909 mm,	Y =     44.533272 mm,	Z =      9.883374 mm,
	W =    171.867693 deg,	P =    -17.858477 deg,	R =      2.509187 deg
};
P[58:"p248"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.306737 mm,	Y =     35.699210 mm,	Z =     10.966320 mm,
	W =    173.415963 deg,	P =    -18.639907 deg,	R =      2.112740 deg
};
P[59:"p251"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.304748 mm,	Y =     26.840823 mm,	Z =     11.815686 mm,
	W =    175.007480 deg,	P =    -19.273312 deg,	R =      1.651630 deg
};
P[60:"p254"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.300688 mm,	Y =     17.964381 mm,	Z =     12.427834 mm,
	W =    176.644221 deg,	P =    -19.725953 deg,	R =      1.133797 deg
};
P[61:"p257"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.303195 mm,	Y =      9.074611 mm,	Z =     12.796485 mm,
	W =    178.297419 deg,	P =    -20.008382 deg,	R =      0.582702 deg
};
P[62:"p260"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.305703 mm,	Y =      0.178386 mm,	Z =     12.922172 mm,
	W =    179.963164 deg,	P =    -20.108550 deg,	R =      0.012664 deg
};
P[63:"p263"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.307797 mm,	Y =     -8.717943 mm,	Z =     12.804450 mm,
	W =   -178.370811 deg,	P =    -20.023872 deg,	R =     -0.557986 deg
};
P[64:"p266"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.312794 mm,	Y =    -17.607400 mm,	Z =     12.443007 mm,
	W =   -176.707187 deg,	P =    -19.742093 deg,	R =     -1.113355 deg
};
P[65:"p269"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.319274 mm,	Y =    -26.485026 mm,	Z =     11.839829 mm,
	W =   -175.078955 deg,	P =    -19.287252 deg,	R =     -1.629012 deg
};
P[66:"p272"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.323309 mm,	Y =    -35.344239 mm,	Z =     10.999289 mm,
	W =   -173.485460 deg,	P =    -18.667628 deg,	R =     -2.093260 deg
};
P[67:"p275"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.330254 mm,	Y =    -44.179228 mm,	Z =      9.923565 mm,
	W =   -171.935305 deg,	P =    -17.898899 deg,	R =     -2.493514 deg
};
P[68:"p278"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.343694 mm,	Y =    -52.984226 mm,	Z =      8.616890 mm,
	W =   -170.430184 deg,	P =    -16.989502 deg,	R =     -2.820283 deg
};
P[69:"p282"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.355301 mm,	Y =    -64.671276 mm,	Z =      6.530222 mm,
	W =   -168.518810 deg,	P =    -15.616171 deg,	R =     -3.129567 deg
};
P[70:"p286"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.385984 mm,	Y =    -76.286826 mm,	Z =      4.057698 mm,
	W =   -166.706711 deg,	P =    -14.101013 deg,	R =     -3.294428 deg
};
P[71:"p289"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.403464 mm,	Y =    -84.947574 mm,	Z =      1.965560 mm,
	W =   -165.413609 deg,	P =    -12.911889 deg,	R =     -3.327905 deg
};
P[72:"p290"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -139.305722 mm,	Y =    -87.826538 mm,	Z =      1.248137 mm,
	W =   -164.980314 deg,	P =    -12.496538 deg,	R =     -3.322789 deg
};
P[73:"p291"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -136.808528 mm,	Y =    -89.390780 mm,	Z =      1.412307 mm,
	W =   -164.451604 deg,	P =    -11.983336 deg,	R =     -3.306247 deg
};
P[74:"p295"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -125.174998 mm,	Y =    -89.356747 mm,	Z =      3.930561 mm,
	W =   -163.332156 deg,	P =    -10.522001 deg,	R =     -3.129523 deg
};
P[75:"p298"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -116.419250 mm,	Y =    -89.282515 mm,	Z =      5.629252 mm,
	W =   -162.957098 deg,	P =     -9.373787 deg,	R =     -2.858356 deg
};
P[76:"p302"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.708624 mm,	Y =    -89.007243 mm,	Z =      7.648860 mm,
	W =   -163.136951 deg,	P =     -7.834890 deg,	R =     -2.366163 deg
};
P[77:"p306"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -92.941950 mm,	Y =    -88.737879 mm,	Z =      9.320626 mm,
	W =   -164.110762 deg,	P =     -6.384915 deg,	R =     -1.813130 deg
};
P[78:"p310"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -81.119770 mm,	Y =    -88.487212 mm,	Z =     10.663442 mm,
	W =   -165.626670 deg,	P =     -5.132961 deg,	R =     -1.313385 deg
};
P[79:"p315"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -66.272070 mm,	Y =    -88.189705 mm,	Z =     11.971135 mm,
	W =   -167.788722 deg,	P =     -3.988894 deg,	R =     -0.862489 deg
};
P[80:"p323"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -42.396538 mm,	Y =    -87.706195 mm,	Z =     13.576748 mm,
	W =   -170.035010 deg,	P =     -3.176088 deg,	R =     -0.557726 deg
};
P[81:"p331"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -18.469860 mm,	Y =    -87.146864 mm,	Z =     14.980918 mm,
	W =   -169.174211 deg,	P =     -2.780703 deg,	R =     -0.531521 deg
};
P[82:"p337"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -0.559333 mm,	Y =    -86.697092 mm,	Z =     15.851290 mm,
	W =   -166.945273 deg,	P =     -1.820898 deg,	R =     -0.422141 deg
};
P[83:"p342"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     14.325738 mm,	Y =    -86.333443 mm,	Z =     16.250130 mm,
	W =   -165.017732 deg,	P =     -0.310166 deg,	R =     -0.083005 deg
};
P[84:"p346"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     26.207224 mm,	Y =    -86.061335 mm,	Z =     16.221604 mm,
	W =   -163.967930 deg,	P =      1.292677 deg,	R =      0.371416 deg
};
P[85:"p349"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     35.102824 mm,	Y =    -85.860142 mm,	Z =     15.952068 mm,
	W =   -163.643406 deg,	P =      2.639128 deg,	R =      0.774245 deg
};
P[86:"p352"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     43.986323 mm,	Y =    -85.655180 mm,	Z =     15.452793 mm,
	W =   -163.770716 deg,	P =      4.014312 deg,	R =      1.167373 deg
};
P[87:"p355"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     52.857394 mm,	Y =    -85.453498 mm,	Z =     14.721393 mm,
	W =   -164.327615 deg,	P =      5.353800 deg,	R =      1.499574 deg
};
P[88:"p359"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     64.665332 mm,	Y =    -85.174969 mm,	Z =     13.417906 mm,
	W =   -165.622121 deg,	P =      7.007504 deg,	R =      1.791279 deg
};
P[89:"p364"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     79.416046 mm,	Y =    -84.844257 mm,	Z =     11.358324 mm,
	W =   -167.688165 deg,	P =      8.506896 deg,	R =      1.849188 deg
};
P[90:"p373"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    106.009007 mm,	Y =    -84.278344 mm,	Z =      7.047655 mm,
	W =   -170.377791 deg,	P =      9.357060 deg,	R =      1.578917 deg
};
P[91:"p377"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    117.852123 mm,	Y =    -84.011748 mm,	Z =      5.093790 mm,
	W =   -170.433262 deg,	P =      9.271505 deg,	R =      1.555429 deg
};
P[92:"p378"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    120.523868 mm,	Y =    -82.655617 mm,	Z =      4.872326 mm,
	W =   -170.489840 deg,	P =      9.179085 deg,	R =      1.530792 deg
};
P[93:"p383"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    131.216140 mm,	Y =    -72.103814 mm,	Z =      4.864051 mm,
	W =   -171.130111 deg,	P =      8.183027 deg,	R =      1.272476 deg
};
P[94:"p384"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    133.286521 mm,	Y =    -69.921791 mm,	Z =      4.899277 mm,
	W =   -171.222836 deg,	P =      7.930806 deg,	R =      1.220426 deg
};
P[95:"p388"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    133.022515 mm,	Y =    -58.154343 mm,	Z =      6.564445 mm,
	W =   -172.846051 deg,	P =      6.863716 deg,	R =      0.859361 deg
};
P[96:"p392"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    132.769043 mm,	Y =    -46.341263 mm,	Z =      7.902473 mm,
	W =   -174.406628 deg,	P =      5.945465 deg,	R =      0.581199 deg
};
P[97:"p396"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    132.514024 mm,	Y =    -34.493321 mm,	Z =      8.925320 mm,
	W =   -175.912518 deg,	P =      5.201448 deg,	R =      0.371187 deg
};
P[98:"p400"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    132.251228 mm,	Y =    -22.618099 mm,	Z =      9.644227 mm,
	W =   -177.343883 deg,	P =      4.685638 deg,	R =      0.217129 deg
};
P[99:"p404"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    131.980257 mm,	Y =    -10.727452 mm,	Z =     10.068122 mm,
	W =   -178.757000 deg,	P =      4.397251 deg,	R =      0.095317 deg
};
P[100:"p408"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    131.698414 mm,	Y =      1.172338 mm,	Z =     10.203993 mm,
	W =    179.863003 deg,	P =      4.352244 deg,	R =     -0.010396 deg
};
P[101:"p412"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    131.405207 mm,	Y =     13.073448 mm,	Z =     10.056878 mm,
	W =    178.501543 deg,	P =      4.546102 deg,	R =     -0.118796 deg
};
P[102:"p416"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    131.104440 mm,	Y =     24.966193 mm,	Z =      9.628223 mm,
	W =    177.112592 deg,	P =      4.964400 deg,	R =     -0.250077 deg
};
P[103:"p420"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    130.797360 mm,	Y =     36.845377 mm,	Z =      8.916676 mm,
	W =    175.716786 deg,	P =      5.581464 deg,	R =     -0.417360 deg
};
P[104:"p424"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    130.497947 mm,	Y =     48.702422 mm,	Z =      7.917097 mm,
	W =    174.288321 deg,	P =      6.363033 deg,	R =     -0.635092 deg
};
P[105:"p428"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    130.201510 mm,	Y =     60.526448 mm,	Z =      6.623150 mm,
	W =    172.781568 deg,	P =      7.263927 deg,	R =     -0.917481 deg
};
P[106:"p430"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    130.056658 mm,	Y =     66.424336 mm,	Z =      5.862589 mm,
	W =    172.011685 deg,	P =      7.748595 deg,	R =     -1.083942 deg
};
P[107:"p431"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    129.340842 mm,	Y =     69.304084 mm,	Z =      5.555414 mm,
	W =    171.688952 deg,	P =      8.001776 deg,	R =     -1.164952 deg
};
P[108:"p436"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    118.144182 mm,	Y =     79.332023 mm,	Z =      5.798855 mm,
	W =    171.044394 deg,	P =      9.130366 deg,	R =     -1.432476 deg
};
P[109:"p438"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    112.213097 mm,	Y =     79.285479 mm,	Z =      6.793828 mm,
	W =    171.162337 deg,	P =      9.347429 deg,	R =     -1.446605 deg
};
P[110:"p447"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     85.608313 mm,	Y =     78.689712 mm,	Z =     11.553519 mm,
	W =    169.381633 deg,	P =      9.695126 deg,	R =     -1.808348 deg
};
P[111:"p453"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     67.951103 mm,	Y =     78.357159 mm,	Z =     14.590651 mm,
	W =    167.060042 deg,	P =      8.388600 deg,	R =     -1.919807 deg
};
P[112:"p457"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     56.194983 mm,	Y =     78.123775 mm,	Z =     16.295025 mm,
	W =    165.736197 deg,	P =      6.633556 deg,	R =     -1.682161 deg
};
P[113:"p460"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.367651 mm,	Y =     77.950611 mm,	Z =     17.305877 mm,
	W =    165.091298 deg,	P =      5.018172 deg,	R =     -1.334100 deg
};
P[114:"p463"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     38.526830 mm,	Y =     77.756875 mm,	Z =     18.045113 mm,
	W =    164.899445 deg,	P =      3.261682 deg,	R =     -0.879559 deg
};
P[115:"p466"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     29.672544 mm,	Y =     77.545750 mm,	Z =     18.491316 mm,
	W =    165.117262 deg,	P =      1.448792 deg,	R =     -0.384980 deg
};
P[116:"p469"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     20.802766 mm,	Y =     77.312093 mm,	Z =     18.647902 mm,
	W =    165.745147 deg,	P =     -0.269890 deg,	R =      0.068567 deg
};
P[117:"p472"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     11.915921 mm,	Y =     77.062501 mm,	Z =     18.539313 mm,
	W =    166.716779 deg,	P =     -1.760690 deg,	R =      0.415592 deg
};
P[118:"p476"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      0.032861 mm,	Y =     76.758331 mm,	Z =     18.055551 mm,
	W =    168.324501 deg,	P =     -3.181656 deg,	R =      0.657104 deg
};
P[119:"p484"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -23.866245 mm,	Y =     76.130760 mm,	Z =     16.555687 mm,
	W =    171.168410 deg,	P =     -3.798206 deg,	R =      0.589685 deg
};
P[120:"p490"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -41.895788 mm,	Y =     75.712126 mm,	Z =     15.529444 mm,
	W =    171.677773 deg,	P =     -2.891216 deg,	R =      0.422741 deg
};
P[121:"p498"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -65.913231 mm,	Y =     75.202006 mm,	Z =     14.569444 mm,
	W =    169.729751 deg,	P =     -2.301338 deg,	R =      0.416870 deg
};
P[122:"p503"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -80.818548 mm,	Y =     74.944483 mm,	Z =     13.883968 mm,
	W =    167.752815 deg,	P =     -3.361739 deg,	R =      0.729274 deg
};
P[123:"p507"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -92.659874 mm,	Y =     74.767458 mm,	Z =     13.017369 mm,
	W =    166.353566 deg,	P =     -5.078048 deg,	R =      1.231063 deg
};
P[124:"p510"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -101.486046 mm,	Y =     74.607951 mm,	Z =     12.088960 mm,
	W =    165.631721 deg,	P =     -6.768249 deg,	R =      1.729243 deg
};
P[125:"p513"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -110.264498 mm,	Y =     74.432737 mm,	Z =     10.870742 mm,
	W =    165.302258 deg,	P =     -8.631613 deg,	R =      2.254379 deg
};
P[126:"p516"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -118.992259 mm,	Y =     74.228526 mm,	Z =      9.348923 mm,
	W =    165.388551 deg,	P =    -10.552199 deg,	R =      2.733294 deg
};
P[127:"p517"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -121.581839 mm,	Y =     72.829496 mm,	Z =      9.172768 mm,
	W =    165.719845 deg,	P =    -11.197465 deg,	R =      2.829657 deg
};
P[128:"p518"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.568144 mm,	Y =     70.652788 mm,	Z =      9.277507 mm,
	W =    166.176233 deg,	P =    -11.781903 deg,	R =      2.876289 deg
};
P[129:"p521"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.456474 mm,	Y =     61.980548 mm,	Z =     11.272747 mm,
	W =    167.654764 deg,	P =    -12.411567 deg,	R =      2.693245 deg
};
P[130:"p524"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.340561 mm,	Y =     53.262078 mm,	Z =     13.039867 mm,
	W =    169.188951 deg,	P =    -12.988875 deg,	R =      2.457657 deg
};
P[131:"p527"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.245084 mm,	Y =     44.505291 mm,	Z =     14.560073 mm,
	W =    170.859793 deg,	P =    -13.488781 deg,	R =      2.149262 deg
};
P[132:"p530"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.140031 mm,	Y =     35.711338 mm,	Z =     15.830268 mm,
	W =    172.576619 deg,	P =    -13.925622 deg,	R =      1.796002 deg
};
P[133:"p533"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -123.009124 mm,	Y =     26.887836 mm,	Z =     16.844543 mm,
	W =    174.355622 deg,	P =    -14.259899 deg,	R =      1.394567 deg
};
P[134:"p536"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -122.855388 mm,	Y =     18.040458 mm,	Z =     17.594154 mm,
	W =    176.175128 deg,	P =    -14.481219 deg,	R =      0.957792 deg
};
P[135:"p539"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -122.691030 mm,	Y =      9.177390 mm,	Z =     18.069496 mm,
	W =    178.046524 deg,	P =    -14.580178 deg,	R =      0.491936 deg
};
P[136:"p542"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -122.508170 mm,	Y =      0.305276 mm,	Z =     18.268363 mm,
	W =    179.934186 deg,	P =    -14.559890 deg,	R =      0.016545 deg
};
P[137:"p545"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -122.307200 mm,	Y =     -8.567748 mm,	Z =     18.188372 mm,
	W =   -178.174197 deg,	P =    -14.420501 deg,	R =     -0.454836 deg
};
P[138:"p548"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -122.086221 mm,	Y =    -17.433608 mm,	Z =     17.830087 mm,
	W =   -176.294210 deg,	P =    -14.166998 deg,	R =     -0.908179 deg
};
P[139:"p551"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -121.836916 mm,	Y =    -26.285115 mm,	Z =     17.197776 mm,
	W =   -174.453479 deg,	P =    -13.800740 deg,	R =     -1.327012 deg
};
P[140:"p554"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -121.560091 mm,	Y =    -35.114417 mm,	Z =     16.295431 mm,
	W =   -172.658033 deg,	P =    -13.353208 deg,	R =     -1.704492 deg
};
P[141:"p557"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -121.281407 mm,	Y =    -43.914335 mm,	Z =     15.123670 mm,
	W =   -170.911090 deg,	P =    -12.842117 deg,	R =     -2.036408 deg
};
P[142:"p560"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -120.995550 mm,	Y =    -52.679350 mm,	Z =     13.692546 mm,
	W =   -169.237174 deg,	P =    -12.285398 deg,	R =     -2.316189 deg
};
P[143:"p563"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -120.683947 mm,	Y =    -61.404694 mm,	Z =     12.016088 mm,
	W =   -167.644909 deg,	P =    -11.689526 deg,	R =     -2.541112 deg
};
P[144:"p565"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -120.479544 mm,	Y =    -67.196681 mm,	Z =     10.764168 mm,
	W =   -166.624855 deg,	P =    -11.294799 deg,	R =     -2.666337 deg
};
P[145:"p566"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -118.698247 mm,	Y =    -69.541225 mm,	Z =     10.574297 mm,
	W =   -166.164525 deg,	P =    -10.737700 deg,	R =     -2.627187 deg
};
P[146:"p569"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -109.986450 mm,	Y =    -69.973967 mm,	Z =     12.040028 mm,
	W =   -166.063036 deg,	P =     -8.580893 deg,	R =     -2.120512 deg
};
P[147:"p572"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -101.219602 mm,	Y =    -70.380762 mm,	Z =     13.168632 mm,
	W =   -166.358760 deg,	P =     -6.487250 deg,	R =     -1.570619 deg
};
P[148:"p575"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -92.418846 mm,	Y =    -70.061161 mm,	Z =     14.143188 mm,
	W =   -167.150614 deg,	P =     -4.604549 deg,	R =     -1.049055 deg
};
P[149:"p578"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -83.567655 mm,	Y =    -69.738002 mm,	Z =     14.830083 mm,
	W =   -168.212846 deg,	P =     -3.052548 deg,	R =     -0.636669 deg
};
P[150:"p582"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -71.688111 mm,	Y =    -69.276327 mm,	Z =     15.424921 mm,
	W =   -169.834265 deg,	P =     -1.797622 deg,	R =     -0.322277 deg
};
P[151:"p589"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -50.709418 mm,	Y =    -68.563231 mm,	Z =     16.151101 mm,
	W =   -172.188277 deg,	P =     -1.962491 deg,	R =     -0.269182 deg
};
P[152:"p594"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -35.640291 mm,	Y =    -68.112761 mm,	Z =     16.907398 mm,
	W =   -172.707577 deg,	P =     -3.338590 deg,	R =     -0.426985 deg
};
P[153:"p599"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -20.594928 mm,	Y =    -67.721534 mm,	Z =     18.039474 mm,
	W =   -172.022449 deg,	P =     -4.635609 deg,	R =     -0.648904 deg
};
P[154:"p606"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      0.310779 mm,	Y =    -67.276574 mm,	Z =     19.913081 mm,
	W =   -169.689237 deg,	P =     -4.459021 deg,	R =     -0.810334 deg
};
P[155:"p610"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     12.172260 mm,	Y =    -67.083585 mm,	Z =     20.763505 mm,
	W =   -168.264161 deg,	P =     -2.914746 deg,	R =     -0.605233 deg
};
P[156:"p613"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     21.035421 mm,	Y =    -66.918465 mm,	Z =     21.131546 mm,
	W =   -167.425430 deg,	P =     -1.106377 deg,	R =     -0.246772 deg
};
P[157:"p616"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     29.876785 mm,	Y =    -66.729769 mm,	Z =     21.183007 mm,
	W =   -166.903563 deg,	P =      1.082423 deg,	R =      0.251800 deg
};
P[158:"p619"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     38.699156 mm,	Y =    -66.503289 mm,	Z =     20.871485 mm,
	W =   -166.785423 deg,	P =      3.435582 deg,	R =      0.806194 deg
};
P[159:"p622"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.499472 mm,	Y =    -66.237847 mm,	Z =     20.182169 mm,
	W =   -167.064130 deg,	P =      5.783842 deg,	R =      1.325996 deg
};
P[160:"p625"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     56.279458 mm,	Y =    -65.934567 mm,	Z =     19.135901 mm,
	W =   -167.718481 deg,	P =      7.922631 deg,	R =      1.718729 deg
};
P[161:"p628"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     65.046936 mm,	Y =    -65.579677 mm,	Z =     17.788187 mm,
	W =   -168.663909 deg,	P =      9.651915 deg,	R =      1.925103 deg
};
P[162:"p632"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     76.743325 mm,	Y =    -65.123368 mm,	Z =     15.639370 mm,
	W =   -170.180929 deg,	P =     11.074248 deg,	R =      1.904038 deg
};
P[163:"p639"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     97.338444 mm,	Y =    -64.361004 mm,	Z =     11.551156 mm,
	W =   -172.529643 deg,	P =     10.956445 deg,	R =      1.427641 deg
};
P[164:"p640"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    100.010868 mm,	Y =    -63.045363 mm,	Z =     11.193563 mm,
	W =   -172.879077 deg,	P =     10.808166 deg,	R =      1.341998 deg
};
P[165:"p646"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    111.975290 mm,	Y =    -49.664474 mm,	Z =     10.392674 mm,
	W =   -174.854602 deg,	P =      9.467762 deg,	R =      0.848601 deg
};
P[166:"p647"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    112.801125 mm,	Y =    -46.800637 mm,	Z =     10.501454 mm,
	W =   -175.168240 deg,	P =      9.325970 deg,	R =      0.784804 deg
};
P[167:"p651"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    112.405945 mm,	Y =    -34.931261 mm,	Z =     11.421245 mm,
	W =   -176.468647 deg,	P =      9.407995 deg,	R =      0.577960 deg
};
P[168:"p656"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    111.931452 mm,	Y =    -20.064223 mm,	Z =     12.205530 mm,
	W =   -178.008092 deg,	P =      9.540119 deg,	R =      0.330265 deg
};
P[169:"p661"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    111.477628 mm,	Y =     -5.177037 mm,	Z =     12.601774 mm,
	W =   -179.489578 deg,	P =      9.684429 deg,	R =      0.085866 deg
};
P[170:"p666"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    111.043291 mm,	Y =      9.717092 mm,	Z =     12.619131 mm,
	W =    179.043784 deg,	P =      9.812135 deg,	R =     -0.162971 deg
};
P[171:"p671"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    110.631610 mm,	Y =     24.605410 mm,	Z =     12.254762 mm,
	W =    177.547895 deg,	P =      9.893727 deg,	R =     -0.421574 deg
};
P[172:"p676"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    110.253732 mm,	Y =     39.474648 mm,	Z =     11.493420 mm,
	W =    175.981395 deg,	P =      9.901390 deg,	R =     -0.692113 deg
};
P[173:"p679"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    110.048359 mm,	Y =     48.380998 mm,	Z =     10.835727 mm,
	W =    174.994651 deg,	P =      9.851240 deg,	R =     -0.858490 deg
};
P[174:"p680"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    109.160416 mm,	Y =     51.223835 mm,	Z =     10.738187 mm,
	W =    174.640856 deg,	P =      9.970169 deg,	R =     -0.930491 deg
};
P[175:"p684"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     99.814058 mm,	Y =     58.704861 mm,	Z =     11.745325 mm,
	W =    173.411329 deg,	P =     11.103052 deg,	R =     -1.274221 deg
};
P[176:"p685"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     97.039504 mm,	Y =     59.782624 mm,	Z =     12.178271 mm,
	W =    173.076155 deg,	P =     11.329692 deg,	R =     -1.366620 deg
};
P[177:"p692"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     76.475497 mm,	Y =     59.411437 mm,	Z =     16.622975 mm,
	W =    170.991508 deg,	P =     11.791327 deg,	R =     -1.855538 deg
};
P[178:"p696"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     64.814296 mm,	Y =     59.262426 mm,	Z =     19.021643 mm,
	W =    169.654655 deg,	P =     10.373827 deg,	R =     -1.882719 deg
};
P[179:"p699"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     56.076496 mm,	Y =     59.130050 mm,	Z =     20.563861 mm,
	W =    168.846599 deg,	P =      8.540109 deg,	R =     -1.677063 deg
};
P[180:"p702"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.327114 mm,	Y =     58.976261 mm,	Z =     21.777447 mm,
	W =    168.320859 deg,	P =      6.184061 deg,	R =     -1.275619 deg
};
P[181:"p705"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     38.560384 mm,	Y =     58.757786 mm,	Z =     22.599210 mm,
	W =    168.128889 deg,	P =      3.484194 deg,	R =     -0.731909 deg
};
P[182:"p708"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     29.771721 mm,	Y =     58.483572 mm,	Z =     22.992913 mm,
	W =    168.353340 deg,	P =      0.722627 deg,	R =     -0.148943 deg
};
P[183:"p711"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     20.962927 mm,	Y =     58.151267 mm,	Z =     22.965110 mm,
	W =    168.931986 deg,	P =     -1.845284 deg,	R =      0.360893 deg
};
P[184:"p714"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     12.133315 mm,	Y =     57.779366 mm,	Z =     22.562769 mm,
	W =    169.787824 deg,	P =     -3.976720 deg,	R =      0.715785 deg
};
P[185:"p718"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      0.309829 mm,	Y =     57.296539 mm,	Z =     21.586753 mm,
	W =    171.192872 deg,	P =     -5.733409 deg,	R =      0.886756 deg
};
P[186:"p724"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -17.570557 mm,	Y =     56.535100 mm,	Z =     19.763213 mm,
	W =    173.206596 deg,	P =     -5.845011 deg,	R =      0.695052 deg
};
P[187:"p728"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -29.617869 mm,	Y =     56.127523 mm,	Z =     18.701673 mm,
	W =    174.014177 deg,	P =     -4.391787 deg,	R =      0.460036 deg
};
P[188:"p731"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -38.696889 mm,	Y =     55.854793 mm,	Z =     18.137871 mm,
	W =    174.191361 deg,	P =     -2.951817 deg,	R =      0.300149 deg
};
P[189:"p735"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -50.816692 mm,	Y =     55.547679 mm,	Z =     17.743792 mm,
	W =    173.821927 deg,	P =     -1.096910 deg,	R =      0.118730 deg
};
P[190:"p740"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -65.894294 mm,	Y =     55.264990 mm,	Z =     17.675357 mm,
	W =    172.553543 deg,	P =      0.034033 deg,	R =     -0.004448 deg
};
P[191:"p745"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -80.822580 mm,	Y =     55.082737 mm,	Z =     17.630808 mm,
	W =    170.893269 deg,	P =     -0.971917 deg,	R =      0.155785 deg
};
P[192:"p748"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -89.699550 mm,	Y =     54.993293 mm,	Z =     17.368511 mm,
	W =    169.974843 deg,	P =     -2.640479 deg,	R =      0.466608 deg
};
P[193:"p751"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -98.514543 mm,	Y =     54.881099 mm,	Z =     16.789286 mm,
	W =    169.267331 deg,	P =     -4.950499 deg,	R =      0.937080 deg
};
P[194:"p752"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -101.315506 mm,	Y =     53.984554 mm,	Z =     16.685743 mm,
	W =    169.254389 deg,	P =     -5.791483 deg,	R =      1.097083 deg
};
P[195:"p753"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -103.736274 mm,	Y =     52.296420 mm,	Z =     16.732129 mm,
	W =    169.446019 deg,	P =     -6.483588 deg,	R =      1.205227 deg
};
P[196:"p754"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.460718 mm,	Y =     49.455211 mm,	Z =     17.158843 mm,
	W =    169.950902 deg,	P =     -6.668097 deg,	R =      1.178826 deg
};
P[197:"p757"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.377865 mm,	Y =     40.686910 mm,	Z =     18.581110 mm,
	W =    171.642877 deg,	P =     -6.424672 deg,	R =      0.941739 deg
};
P[198:"p760"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.269782 mm,	Y =     31.884936 mm,	Z =     19.743327 mm,
	W =    173.392907 deg,	P =     -6.195293 deg,	R =      0.716162 deg
};
P[199:"p763"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -104.131607 mm,	Y =     23.055392 mm,	Z =     20.636492 mm,
	W =    175.188327 deg,	P =     -5.996312 deg,	R =      0.503821 deg
};
P[200:"p766"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -103.961122 mm,	Y =     14.205792 mm,	Z =     21.253588 mm,
	W =    177.023807 deg,	P =     -5.810486 deg,	R =      0.301573 deg
};
P[201:"p769"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -103.750448 mm,	Y =      5.343520 mm,	Z =     21.590289 mm,
	W =    178.879311 deg,	P =     -5.626501 deg,	R =      0.109890 deg
};
P[202:"p772"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -103.509737 mm,	Y =     -3.523909 mm,	Z =     21.643182 mm,
	W =   -179.260511 deg,	P =     -5.514095 deg,	R =     -0.071062 deg
};
P[203:"p775"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -103.232338 mm,	Y =    -12.388529 mm,	Z =     21.413316 mm,
	W =   -177.415594 deg,	P =     -5.440811 deg,	R =     -0.245212 deg
};
P[204:"p778"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -102.917411 mm,	Y =    -21.241654 mm,	Z =     20.903994 mm,
	W =   -175.589342 deg,	P =     -5.415063 deg,	R =     -0.417051 deg
};
P[205:"p781"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -102.564872 mm,	Y =    -30.076677 mm,	Z =     20.120972 mm,
	W =   -173.807557 deg,	P =     -5.443828 deg,	R =     -0.589753 deg
};
P[206:"p784"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -102.178856 mm,	Y =    -38.886593 mm,	Z =     19.072061 mm,
	W =   -172.077163 deg,	P =     -5.530908 deg,	R =     -0.768483 deg
};
P[207:"p787"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -101.764970 mm,	Y =    -47.665805 mm,	Z =     17.766968 mm,
	W =   -170.410253 deg,	P =     -5.679480 deg,	R =     -0.957907 deg
};
P[208:"p788"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =   -101.624416 mm,	Y =    -50.584410 mm,	Z =     17.276634 mm,
	W =   -169.867952 deg,	P =     -5.734001 deg,	R =     -1.022872 deg
};
P[209:"p789"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -98.719783 mm,	Y =    -50.954582 mm,	Z =     17.488108 mm,
	W =   -169.969492 deg,	P =     -4.814563 deg,	R =     -0.850517 deg
};
P[210:"p792"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -89.915757 mm,	Y =    -50.887742 mm,	Z =     18.058496 mm,
	W =   -170.665448 deg,	P =     -2.341122 deg,	R =     -0.384710 deg
};
P[211:"p795"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -81.046845 mm,	Y =    -50.835051 mm,	Z =     18.283624 mm,
	W =   -171.548414 deg,	P =     -0.548304 deg,	R =     -0.081470 deg
};
P[212:"p800"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -66.152761 mm,	Y =    -50.055917 mm,	Z =     18.325642 mm,
	W =   -173.240213 deg,	P =      0.566092 deg,	R =      0.067098 deg
};
P[213:"p805"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -51.085976 mm,	Y =    -49.332266 mm,	Z =     18.372063 mm,
	W =   -174.551391 deg,	P =     -0.713113 deg,	R =     -0.068018 deg
};
P[214:"p808"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -41.990317 mm,	Y =    -48.942407 mm,	Z =     18.640861 mm,
	W =   -174.945176 deg,	P =     -2.278991 deg,	R =     -0.201529 deg
};
P[215:"p811"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -32.890177 mm,	Y =    -48.613356 mm,	Z =     19.176558 mm,
	W =   -174.983379 deg,	P =     -4.025893 deg,	R =     -0.353102 deg
};
P[216:"p814"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -23.815388 mm,	Y =    -48.318241 mm,	Z =     19.986116 mm,
	W =   -174.660991 deg,	P =     -5.666696 deg,	R =     -0.528697 deg
};
P[217:"p818"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -11.803896 mm,	Y =    -48.024808 mm,	Z =     21.383412 mm,
	W =   -173.792880 deg,	P =     -7.006362 deg,	R =     -0.760073 deg
};
P[218:"p824"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      5.998887 mm,	Y =    -47.677143 mm,	Z =     23.608713 mm,
	W =   -172.060442 deg,	P =     -6.151505 deg,	R =     -0.856210 deg
};
P[219:"p827"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     14.830719 mm,	Y =    -47.520588 mm,	Z =     24.475248 mm,
	W =   -171.269592 deg,	P =     -4.359620 deg,	R =     -0.668807 deg
};
P[220:"p830"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     23.634732 mm,	Y =    -47.357093 mm,	Z =     24.997075 mm,
	W =   -170.694523 deg,	P =     -1.817049 deg,	R =     -0.297679 deg
};
P[221:"p832"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     29.486668 mm,	Y =    -47.204138 mm,	Z =     25.106789 mm,
	W =   -170.445937 deg,	P =      0.237140 deg,	R =      0.039914 deg
};
P[222:"p834"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     35.329786 mm,	Y =    -47.024868 mm,	Z =     25.000466 mm,
	W =   -170.354219 deg,	P =      2.398862 deg,	R =      0.407583 deg
};
P[223:"p836"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     41.160755 mm,	Y =    -46.808920 mm,	Z =     24.670571 mm,
	W =   -170.402098 deg,	P =      4.593641 deg,	R =      0.775904 deg
};
P[224:"p838"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     46.978201 mm,	Y =    -46.557775 mm,	Z =     24.118500 mm,
	W =   -170.587725 deg,	P =      6.721967 deg,	R =      1.111600 deg
};
P[225:"p841"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     55.679854 mm,	Y =    -46.116907 mm,	Z =     22.902380 mm,
	W =   -171.111032 deg,	P =      9.574603 deg,	R =      1.490158 deg
};
P[226:"p844"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     64.361362 mm,	Y =    -45.618057 mm,	Z =     21.291748 mm,
	W =   -171.868575 deg,	P =     11.779159 deg,	R =      1.670710 deg
};
P[227:"p848"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     75.945715 mm,	Y =    -44.939150 mm,	Z =     18.719012 mm,
	W =   -173.085342 deg,	P =     13.389643 deg,	R =      1.608638 deg
};
P[228:"p849"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     78.828903 mm,	Y =    -44.529762 mm,	Z =     18.064263 mm,
	W =   -173.435009 deg,	P =     13.578195 deg,	R =      1.547681 deg
};
P[229:"p853"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     87.118391 mm,	Y =    -36.102040 mm,	Z =     16.791649 mm,
	W =   -175.319323 deg,	P =     14.079818 deg,	R =      1.141073 deg
};
P[230:"p855"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     91.284251 mm,	Y =    -31.885114 mm,	Z =     16.051827 mm,
	W =   -176.131876 deg,	P =     13.879835 deg,	R =      0.929241 deg
};
P[231:"p856"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     92.308091 mm,	Y =    -29.092710 mm,	Z =     15.971489 mm,
	W =   -176.526690 deg,	P =     13.902516 deg,	R =      0.835499 deg
};
P[232:"p860"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     91.811287 mm,	Y =    -17.214646 mm,	Z =     16.653026 mm,
	W =   -177.942537 deg,	P =     14.433448 deg,	R =      0.513040 deg
};
P[233:"p864"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     91.344564 mm,	Y =     -5.322251 mm,	Z =     17.045841 mm,
	W =   -179.356878 deg,	P =     14.739895 deg,	R =      0.163637 deg
};
P[234:"p868"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     90.902822 mm,	Y =      6.574967 mm,	Z =     17.147225 mm,
	W =    179.201758 deg,	P =     14.793918 deg,	R =     -0.203838 deg
};
P[235:"p872"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     90.488434 mm,	Y =     18.470178 mm,	Z =     16.950172 mm,
	W =    177.745561 deg,	P =     14.587879 deg,	R =     -0.568088 deg
};
P[236:"p876"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     90.103913 mm,	Y =     30.353995 mm,	Z =     16.446393 mm,
	W =    176.256681 deg,	P =     14.117503 deg,	R =     -0.914261 deg
};
P[237:"p877"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     88.243642 mm,	Y =     32.665301 mm,	Z =     16.763373 mm,
	W =    175.844797 deg,	P =     14.211347 deg,	R =     -1.021783 deg
};
P[238:"p881"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     79.132939 mm,	Y =     40.161910 mm,	Z =     18.451887 mm,
	W =    174.104812 deg,	P =     13.986587 deg,	R =     -1.429589 deg
};
P[239:"p882"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     76.232067 mm,	Y =     40.316580 mm,	Z =     19.164162 mm,
	W =    173.821106 deg,	P =     13.859928 deg,	R =     -1.485580 deg
};
P[240:"p886"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     64.664578 mm,	Y =     40.170746 mm,	Z =     21.941176 mm,
	W =    172.834564 deg,	P =     12.338038 deg,	R =     -1.538765 deg
};
P[241:"p889"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     56.000077 mm,	Y =     40.032655 mm,	Z =     23.722892 mm,
	W =    172.247778 deg,	P =     10.129168 deg,	R =     -1.371486 deg
};
P[242:"p891"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     50.216120 mm,	Y =     39.916841 mm,	Z =     24.694197 mm,
	W =    171.974714 deg,	P =      8.211541 deg,	R =     -1.153637 deg
};
P[243:"p893"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     44.420340 mm,	Y =     39.762478 mm,	Z =     25.458350 mm,
	W =    171.822632 deg,	P =      6.046324 deg,	R =     -0.867173 deg
};
P[244:"p895"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     38.612414 mm,	Y =     39.562060 mm,	Z =     25.994142 mm,
	W =    171.792280 deg,	P =      3.720205 deg,	R =     -0.536209 deg
};
P[245:"p897"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     32.795892 mm,	Y =     39.325784 mm,	Z =     26.288024 mm,
	W =    171.886588 deg,	P =      1.297879 deg,	R =     -0.185009 deg
};
P[246:"p899"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     26.967456 mm,	Y =     39.047689 mm,	Z =     26.340644 mm,
	W =    172.106481 deg,	P =     -1.026001 deg,	R =      0.142243 deg
};
P[247:"p901"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     21.129894 mm,	Y =     38.729885 mm,	Z =     26.164550 mm,
	W =    172.435711 deg,	P =     -3.154715 deg,	R =      0.418709 deg
};
P[248:"p904"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     12.355657 mm,	Y =     38.230243 mm,	Z =     25.519914 mm,
	W =    173.097386 deg,	P =     -5.790940 deg,	R =      0.699821 deg
};
P[249:"p907"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      3.548827 mm,	Y =     37.697590 mm,	Z =     24.530322 mm,
	W =    173.892036 deg,	P =     -7.488631 deg,	R =      0.799025 deg
};
P[250:"p912"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -11.253298 mm,	Y =     36.820511 mm,	Z =     22.523345 mm,
	W =    175.229632 deg,	P =     -7.962345 deg,	R =      0.662304 deg
};
P[251:"p916"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -23.252595 mm,	Y =     36.217955 mm,	Z =     21.022937 mm,
	W =    176.037152 deg,	P =     -6.390399 deg,	R =      0.441770 deg
};
P[252:"p919"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -32.340659 mm,	Y =     35.819161 mm,	Z =     20.180264 mm,
	W =    176.373123 deg,	P =     -4.432070 deg,	R =      0.280647 deg
};
P[253:"p922"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -41.477736 mm,	Y =     35.482528 mm,	Z =     19.673098 mm,
	W =    176.427173 deg,	P =     -2.172502 deg,	R =      0.135615 deg
};
P[254:"p925"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -50.617433 mm,	Y =     35.202178 mm,	Z =     19.514835 mm,
	W =    176.212591 deg,	P =     -0.092845 deg,	R =      0.006146 deg
};
P[255:"p929"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -62.738103 mm,	Y =     34.931237 mm,	Z =     19.730410 mm,
	W =    175.561552 deg,	P =      1.695374 deg,	R =     -0.131577 deg
};
P[256:"p934"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -77.711545 mm,	Y =     34.719080 mm,	Z =     20.230826 mm,
	W =    174.450320 deg,	P =      1.440688 deg,	R =     -0.139968 deg
};
P[257:"p935"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -80.680046 mm,	Y =     34.678750 mm,	Z =     20.300163 mm,
	W =    174.223503 deg,	P =      1.003672 deg,	R =     -0.101528 deg
};
P[258:"p936"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -83.198817 mm,	Y =     33.101552 mm,	Z =     20.496146 mm,
	W =    174.284909 deg,	P =      0.676266 deg,	R =     -0.067679 deg
};
P[259:"p937"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -84.435229 mm,	Y =     30.411404 mm,	Z =     20.770334 mm,
	W =    174.672594 deg,	P =      0.606748 deg,	R =     -0.056578 deg
};
P[260:"p938"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -84.770653 mm,	Y =     27.474446 mm,	Z =     21.035652 mm,
	W =    175.145375 deg,	P =      0.701555 deg,	R =     -0.059583 deg
};
P[261:"p941"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -84.549274 mm,	Y =     18.610290 mm,	Z =     21.661152 mm,
	W =    176.718894 deg,	P =      1.216157 deg,	R =     -0.069716 deg
};
P[262:"p944"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -84.282310 mm,	Y =      9.732884 mm,	Z =     22.041626 mm,
	W =    178.287195 deg,	P =      1.576382 deg,	R =     -0.047133 deg
};
P[263:"p947"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -83.971679 mm,	Y =      0.849112 mm,	Z =     22.176694 mm,
	W =    179.851215 deg,	P =      1.774519 deg,	R =     -0.004607 deg
};
P[264:"p950"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -83.620981 mm,	Y =     -8.034955 mm,	Z =     22.068373 mm,
	W =   -178.597350 deg,	P =      1.768242 deg,	R =      0.043290 deg
};
P[265:"p953"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -83.226936 mm,	Y =    -16.912695 mm,	Z =     21.720357 mm,
	W =   -177.062315 deg,	P =      1.596675 deg,	R =      0.081926 deg
};
P[266:"p956"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -82.787280 mm,	Y =    -25.779190 mm,	Z =     21.138515 mm,
	W =   -175.562987 deg,	P =      1.238605 deg,	R =      0.096103 deg
};
P[267:"p957"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -82.630906 mm,	Y =    -28.731474 mm,	Z =     20.893808 mm,
	W =   -175.075058 deg,	P =      1.080845 deg,	R =      0.093129 deg
};
P[268:"p958"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -81.109721 mm,	Y =    -31.277498 mm,	Z =     20.636639 mm,
	W =   -174.750809 deg,	P =      1.180261 deg,	R =      0.108426 deg
};
P[269:"p963"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -66.192759 mm,	Y =    -30.935914 mm,	Z =     20.149000 mm,
	W =   -175.852196 deg,	P =      2.171002 deg,	R =      0.157402 deg
};
P[270:"p965"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -60.165841 mm,	Y =    -30.767889 mm,	Z =     19.950901 mm,
	W =   -176.247338 deg,	P =      1.694989 deg,	R =      0.111158 deg
};
P[271:"p968"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -51.084660 mm,	Y =    -30.156310 mm,	Z =     19.825312 mm,
	W =   -176.751539 deg,	P =      0.185824 deg,	R =      0.010547 deg
};
P[272:"p971"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -41.953352 mm,	Y =    -29.607897 mm,	Z =     19.990337 mm,
	W =   -177.038792 deg,	P =     -1.979391 deg,	R =     -0.102371 deg
};
P[273:"p974"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -32.814806 mm,	Y =    -29.134992 mm,	Z =     20.523968 mm,
	W =   -177.085989 deg,	P =     -4.374353 deg,	R =     -0.222450 deg
};
P[274:"p977"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -23.713892 mm,	Y =    -28.721867 mm,	Z =     21.429372 mm,
	W =   -176.910135 deg,	P =     -6.595513 deg,	R =     -0.355240 deg
};
P[275:"p980"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -14.690736 mm,	Y =    -28.370202 mm,	Z =     22.632784 mm,
	W =   -176.530819 deg,	P =     -8.153262 deg,	R =     -0.492594 deg
};
P[276:"p985"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      0.159141 mm,	Y =    -27.931807 mm,	Z =     24.927221 mm,
	W =   -175.671393 deg,	P =     -8.579564 deg,	R =     -0.646957 deg
};
P[277:"p989"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     11.907223 mm,	Y =    -27.637243 mm,	Z =     26.568909 mm,
	W =   -174.994960 deg,	P =     -6.641235 deg,	R =     -0.580300 deg
};
P[278:"p992"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     20.671180 mm,	Y =    -27.386074 mm,	Z =     27.421728 mm,
	W =   -174.612621 deg,	P =     -3.907448 deg,	R =     -0.368204 deg
};
P[279:"p994"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     26.500125 mm,	Y =    -27.191155 mm,	Z =     27.728049 mm,
	W =   -174.452854 deg,	P =     -1.625217 deg,	R =     -0.157819 deg
};
P[280:"p996"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     32.317216 mm,	Y =    -26.949692 mm,	Z =     27.789873 mm,
	W =   -174.377653 deg,	P =      0.906389 deg,	R =      0.089225 deg
};
P[281:"p998"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     38.118291 mm,	Y =    -26.654989 mm,	Z =     27.589588 mm,
	W =   -174.393170 deg,	P =      3.582492 deg,	R =      0.351464 deg
};
P[282:"p1000"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     43.904605 mm,	Y =    -26.320438 mm,	Z =     27.121052 mm,
	W =   -174.498619 deg,	P =      6.214170 deg,	R =      0.597313 deg
};
P[283:"p1002"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     49.674018 mm,	Y =    -25.937550 mm,	Z =     26.395128 mm,
	W =   -174.691261 deg,	P =      8.663690 deg,	R =      0.801922 deg
};
P[284:"p1004"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     55.426793 mm,	Y =    -25.514785 mm,	Z =     25.433587 mm,
	W =   -174.962374 deg,	P =     10.820967 deg,	R =      0.948126 deg
};
P[285:"p1005"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     58.296005 mm,	Y =    -25.291281 mm,	Z =     24.874347 mm,
	W =   -175.122708 deg,	P =     11.789507 deg,	R =      0.998825 deg
};
P[286:"p1006"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     61.137327 mm,	Y =    -24.800071 mm,	Z =     24.295764 mm,
	W =   -175.341053 deg,	P =     12.612321 deg,	R =      1.019436 deg
};
P[287:"p1009"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     66.887008 mm,	Y =    -18.139761 mm,	Z =     23.353315 mm,
	W =   -176.802200 deg,	P =     14.287926 deg,	R =      0.789971 deg
};
P[288:"p1011"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     70.731647 mm,	Y =    -13.710309 mm,	Z =     22.547702 mm,
	W =   -177.699668 deg,	P =     15.058994 deg,	R =      0.597957 deg
};
P[289:"p1012"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     71.904732 mm,	Y =    -10.997391 mm,	Z =     22.322838 mm,
	W =   -178.183985 deg,	P =     15.304768 deg,	R =      0.479493 deg
};
P[290:"p1016"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     71.289664 mm,	Y =      0.855095 mm,	Z =     22.659635 mm,
	W =    179.864883 deg,	P =     15.374021 deg,	R =     -0.035822 deg
};
P[291:"p1019"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     70.834692 mm,	Y =      9.745583 mm,	Z =     22.651210 mm,
	W =    178.370339 deg,	P =     15.189125 deg,	R =     -0.427088 deg
};
P[292:"p1020"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     70.376576 mm,	Y =     12.674918 mm,	Z =     22.682032 mm,
	W =    177.852754 deg,	P =     15.044082 deg,	R =     -0.557587 deg
};
P[293:"p1023"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     63.208118 mm,	Y =     17.644993 mm,	Z =     24.293788 mm,
	W =    176.745281 deg,	P =     13.514976 deg,	R =     -0.761401 deg
};
P[294:"p1025"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     58.398535 mm,	Y =     20.914340 mm,	Z =     25.186532 mm,
	W =    175.961425 deg,	P =     12.026622 deg,	R =     -0.842838 deg
};
P[295:"p1027"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     52.651772 mm,	Y =     20.734580 mm,	Z =     26.328134 mm,
	W =    175.813110 deg,	P =     10.044302 deg,	R =     -0.731497 deg
};
P[296:"p1029"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     46.895385 mm,	Y =     20.517811 mm,	Z =     27.247301 mm,
	W =    175.735778 deg,	P =      7.659390 deg,	R =     -0.569384 deg
};
P[297:"p1031"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     41.124343 mm,	Y =     20.253076 mm,	Z =     27.914074 mm,
	W =    175.728065 deg,	P =      5.023746 deg,	R =     -0.374777 deg
};
P[298:"p1033"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     35.339715 mm,	Y =     19.936666 mm,	Z =     28.309228 mm,
	W =    175.791144 deg,	P =      2.267537 deg,	R =     -0.166826 deg
};
P[299:"p1035"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     29.543747 mm,	Y =     19.570258 mm,	Z =     28.427063 mm,
	W =    175.930291 deg,	P =     -0.455627 deg,	R =      0.032417 deg
};
P[300:"p1037"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     23.740370 mm,	Y =     19.155929 mm,	Z =     28.276638 mm,
	W =    176.130389 deg,	P =     -3.013545 deg,	R =      0.203742 deg
};
P[301:"p1039"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     17.931342 mm,	Y =     18.703328 mm,	Z =     27.880668 mm,
	W =    176.384549 deg,	P =     -5.283525 deg,	R =      0.333365 deg
};
P[302:"p1042"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      9.190813 mm,	Y =     18.012140 mm,	Z =     26.903809 mm,
	W =    176.830732 deg,	P =     -7.794699 deg,	R =      0.430259 deg
};
P[303:"p1046"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -2.525924 mm,	Y =     17.049304 mm,	Z =     25.142288 mm,
	W =    177.459181 deg,	P =     -9.361413 deg,	R =      0.413557 deg
};
P[304:"p1051"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -17.373295 mm,	Y =     15.914483 mm,	Z =     22.813232 mm,
	W =    178.142360 deg,	P =     -8.284977 deg,	R =      0.267772 deg
};
P[305:"p1054"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -26.417959 mm,	Y =     15.319183 mm,	Z =     21.664093 mm,
	W =    178.410000 deg,	P =     -6.301636 deg,	R =      0.174567 deg
};
P[306:"p1057"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -35.547121 mm,	Y =     14.796175 mm,	Z =     20.871336 mm,
	W =    178.555143 deg,	P =     -3.725157 deg,	R =      0.093893 deg
};
P[307:"p1060"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -44.715338 mm,	Y =     14.343548 mm,	Z =     20.502270 mm,
	W =    178.566253 deg,	P =     -1.035519 deg,	R =      0.025916 deg
};
P[308:"p1063"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -53.870251 mm,	Y =     13.970406 mm,	Z =     20.539382 mm,
	W =    178.462367 deg,	P =      1.298890 deg,	R =     -0.034863 deg
};
P[309:"p1065"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -59.939350 mm,	Y =     13.759332 mm,	Z =     20.743704 mm,
	W =    178.342750 deg,	P =      2.387558 deg,	R =     -0.069058 deg
};
P[310:"p1066"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -62.602566 mm,	Y =     12.344785 mm,	Z =     20.903284 mm,
	W =    178.444324 deg,	P =      2.763748 deg,	R =     -0.075030 deg
};
P[311:"p1067"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -63.935722 mm,	Y =      9.674346 mm,	Z =     21.035564 mm,
	W =    178.757591 deg,	P =      2.997516 deg,	R =     -0.064979 deg
};
P[312:"p1071"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -63.310655 mm,	Y =     -2.203271 mm,	Z =     21.101460 mm,
	W =   -179.726741 deg,	P =      3.011351 deg,	R =      0.014355 deg
};
P[313:"p1073"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -62.969379 mm,	Y =     -8.140827 mm,	Z =     21.016061 mm,
	W =   -178.972586 deg,	P =      2.901482 deg,	R =      0.052012 deg
};
P[314:"p1074"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -61.864168 mm,	Y =    -10.910047 mm,	Z =     20.904222 mm,
	W =   -178.642153 deg,	P =      2.701048 deg,	R =      0.064000 deg
};
P[315:"p1077"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -52.757706 mm,	Y =    -10.848837 mm,	Z =     20.589892 mm,
	W =   -178.822158 deg,	P =      1.090892 deg,	R =      0.022428 deg
};
P[316:"p1079"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -46.654289 mm,	Y =    -10.613429 mm,	Z =     20.558528 mm,
	W =   -178.921739 deg,	P =     -0.467980 deg,	R =     -0.008808 deg
};
P[317:"p1082"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -37.480399 mm,	Y =    -10.217798 mm,	Z =     20.851919 mm,
	W =   -179.005656 deg,	P =     -3.165391 deg,	R =     -0.054912 deg
};
P[318:"p1085"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -28.328769 mm,	Y =     -9.901599 mm,	Z =     21.581825 mm,
	W =   -178.995325 deg,	P =     -5.843896 deg,	R =     -0.102305 deg
};
P[319:"p1088"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -19.247974 mm,	Y =     -9.660026 mm,	Z =     22.703073 mm,
	W =   -178.910789 deg,	P =     -8.040570 deg,	R =     -0.152371 deg
};
P[320:"p1092"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -7.291063 mm,	Y =     -9.462105 mm,	Z =     24.593635 mm,
	W =   -178.700180 deg,	P =     -9.575388 deg,	R =     -0.216255 deg
};
P[321:"p1097"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =      7.433857 mm,	Y =     -9.339116 mm,	Z =     27.009378 mm,
	W =   -178.392476 deg,	P =     -8.461556 deg,	R =     -0.236601 deg
};
P[322:"p1100"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     16.194446 mm,	Y =     -9.257567 mm,	Z =     28.147960 mm,
	W =   -178.234910 deg,	P =     -6.099209 deg,	R =     -0.187600 deg
};
P[323:"p1102"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     22.020630 mm,	Y =     -9.184567 mm,	Z =     28.667208 mm,
	W =   -178.163452 deg,	P =     -3.950233 deg,	R =     -0.126563 deg
};
P[324:"p1104"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     27.835879 mm,	Y =     -9.071269 mm,	Z =     28.945182 mm,
	W =   -178.118771 deg,	P =     -1.419832 deg,	R =     -0.046630 deg
};
P[325:"p1106"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     33.635459 mm,	Y =     -8.908364 mm,	Z =     28.951397 mm,
	W =   -178.115446 deg,	P =      1.411534 deg,	R =      0.046440 deg
};
P[326:"p1108"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     39.423065 mm,	Y =     -8.686812 mm,	Z =     28.670570 mm,
	W =   -178.152889 deg,	P =      4.287975 deg,	R =      0.138155 deg
};
P[327:"p1110"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     45.193576 mm,	Y =     -8.414205 mm,	Z =     28.102833 mm,
	W =   -178.228017 deg,	P =      7.075936 deg,	R =      0.218350 deg
};
P[328:"p1111"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     48.069439 mm,	Y =     -8.255392 mm,	Z =     27.716101 mm,
	W =   -178.280593 deg,	P =      8.419547 deg,	R =      0.251830 deg
};
P[329:"p1112"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     50.824566 mm,	Y =     -7.388328 mm,	Z =     27.303333 mm,
	W =   -178.488162 deg,	P =      9.589329 deg,	R =      0.251907 deg
};
P[330:"p1114"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     54.527782 mm,	Y =     -2.856289 mm,	Z =     26.706096 mm,
	W =   -179.428250 deg,	P =     11.105684 deg,	R =      0.110134 deg
};
P[331:"p1115"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     56.099496 mm,	Y =     -0.378300 mm,	Z =     26.402846 mm,
	W =   -179.922906 deg,	P =     11.686955 deg,	R =      0.015616 deg
};
P[332:"p1116"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     55.005206 mm,	Y =      2.358382 mm,	Z =     26.616058 mm,
	W =    179.525408 deg,	P =     11.282652 deg,	R =     -0.092856 deg
};
P[333:"p1118"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     50.475978 mm,	Y =      6.006574 mm,	Z =     27.394642 mm,
	W =    178.766244 deg,	P =      9.455233 deg,	R =     -0.202708 deg
};
P[334:"p1119"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.699529 mm,	Y =      6.795727 mm,	Z =     27.809965 mm,
	W =    178.583219 deg,	P =      8.259427 deg,	R =     -0.203569 deg
};
P[335:"p1121"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     41.935932 mm,	Y =      6.626341 mm,	Z =     28.513009 mm,
	W =    178.597011 deg,	P =      5.526273 deg,	R =     -0.135138 deg
};
P[336:"p1123"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     36.156588 mm,	Y =      6.400861 mm,	Z =     28.932859 mm,
	W =    178.642148 deg,	P =      2.653478 deg,	R =     -0.062874 deg
};
P[337:"p1125"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     30.364854 mm,	Y =      6.120328 mm,	Z =     29.062251 mm,
	W =    178.718270 deg,	P =     -0.203922 deg,	R =      0.004563 deg
};
P[338:"p1127"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     24.564646 mm,	Y =      5.786171 mm,	Z =     28.909774 mm,
	W =    178.820261 deg,	P =     -2.891249 deg,	R =      0.059515 deg
};
P[339:"p1129"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     18.757916 mm,	Y =      5.407665 mm,	Z =     28.499132 mm,
	W =    178.942463 deg,	P =     -5.268081 deg,	R =      0.097110 deg
};
P[340:"p1132"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     10.025497 mm,	Y =      4.811382 mm,	Z =     27.481304 mm,
	W =    179.135506 deg,	P =     -7.946933 deg,	R =      0.119530 deg
};
P[341:"p1136"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -1.679265 mm,	Y =      3.980239 mm,	Z =     25.638948 mm,
	W =    179.398449 deg,	P =     -9.675101 deg,	R =      0.101101 deg
};
P[342:"p1141"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -16.516785 mm,	Y =      3.000570 mm,	Z =     23.188262 mm,
	W =    179.655700 deg,	P =     -8.644357 deg,	R =      0.051749 deg
};
P[343:"p1144"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -25.560360 mm,	Y =      2.503542 mm,	Z =     21.966959 mm,
	W =    179.739482 deg,	P =     -6.637003 deg,	R =      0.030110 deg
};
P[344:"p1147"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -34.693191 mm,	Y =      2.084861 mm,	Z =     21.111372 mm,
	W =    179.794170 deg,	P =     -4.008872 deg,	R =      0.014390 deg
};
P[345:"p1149"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -40.810198 mm,	Y =      1.849869 mm,	Z =     20.783785 mm,
	W =    179.816619 deg,	P =     -2.137411 deg,	R =      0.006839 deg
};
P[346:"p1152"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -49.987126 mm,	Y =      1.564923 mm,	Z =     20.658797 mm,
	W =    179.832887 deg,	P =      0.484989 deg,	R =     -0.001415 deg
};
P[347:"p1153"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -52.609668 mm,	Y =      0.041323 mm,	Z =     20.698117 mm,
	W =    179.996541 deg,	P =      1.133862 deg,	R =     -0.000068 deg
};
P[348:"p1154"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -49.709569 mm,	Y =     -0.887285 mm,	Z =     20.658040 mm,
	W =   -179.905776 deg,	P =      0.418493 deg,	R =      0.000688 deg
};
P[349:"p1157"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -40.527399 mm,	Y =     -0.815664 mm,	Z =     20.796912 mm,
	W =   -179.918321 deg,	P =     -2.221154 deg,	R =     -0.003166 deg
};
P[350:"p1159"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -34.406112 mm,	Y =     -0.813380 mm,	Z =     21.134881 mm,
	W =   -179.919435 deg,	P =     -4.095143 deg,	R =     -0.005753 deg
};
P[351:"p1162"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -25.265715 mm,	Y =     -0.872126 mm,	Z =     22.006533 mm,
	W =   -179.908489 deg,	P =     -6.713618 deg,	R =     -0.010698 deg
};
P[352:"p1165"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -16.212564 mm,	Y =     -1.017422 mm,	Z =     23.242791 mm,
	W =   -179.883464 deg,	P =     -8.701725 deg,	R =     -0.017631 deg
};
P[353:"p1170"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -1.354748 mm,	Y =     -1.417870 mm,	Z =     25.712272 mm,
	W =   -179.788238 deg,	P =     -9.667602 deg,	R =     -0.035562 deg
};
P[354:"p1174"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     10.368900 mm,	Y =     -1.809451 mm,	Z =     27.559875 mm,
	W =   -179.673173 deg,	P =     -7.883200 deg,	R =     -0.044826 deg
};
P[355:"p1177"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     19.114783 mm,	Y =     -2.077806 mm,	Z =     28.574213 mm,
	W =   -179.589209 deg,	P =     -5.153509 deg,	R =     -0.036900 deg
};
P[356:"p1179"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     24.930651 mm,	Y =     -2.225678 mm,	Z =     28.978710 mm,
	W =   -179.543946 deg,	P =     -2.749096 deg,	R =     -0.021874 deg
};
P[357:"p1181"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     30.738172 mm,	Y =     -2.327224 mm,	Z =     29.121827 mm,
	W =   -179.512411 deg,	P =     -0.036247 deg,	R =     -0.000308 deg
};
P[358:"p1183"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     36.534863 mm,	Y =     -2.370237 mm,	Z =     28.980254 mm,
	W =   -179.498421 deg,	P =      2.841861 deg,	R =      0.024869 deg
};
P[359:"p1185"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     42.316736 mm,	Y =     -2.355842 mm,	Z =     28.546134 mm,
	W =   -179.502359 deg,	P =      5.726114 deg,	R =      0.049653 deg
};
P[360:"p1187"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     48.079969 mm,	Y =     -2.286069 mm,	Z =     27.827664 mm,
	W =   -179.533891 deg,	P =      8.466172 deg,	R =      0.068625 deg
};
P[361:"p1188"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     50.784597 mm,	Y =     -1.270401 mm,	Z =     27.403720 mm,
	W =   -179.740393 deg,	P =      9.612918 deg,	R =      0.043352 deg
};
P[362:"p1189"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     50.682049 mm,	Y =      1.686556 mm,	Z =     27.418980 mm,
	W =    179.653421 deg,	P =      9.569438 deg,	R =     -0.057617 deg
};
P[363:"p1190"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     47.862356 mm,	Y =      2.287285 mm,	Z =     27.859914 mm,
	W =    179.523753 deg,	P =      8.374238 deg,	R =     -0.069361 deg
};
P[364:"p1192"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     42.098871 mm,	Y =      2.355663 mm,	Z =     28.567781 mm,
	W =    179.501672 deg,	P =      5.618809 deg,	R =     -0.048792 deg
};
P[365:"p1194"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     36.316284 mm,	Y =      2.367198 mm,	Z =     28.990918 mm,
	W =    179.500829 deg,	P =      2.733116 deg,	R =     -0.023803 deg
};
P[366:"p1196"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     30.519118 mm,	Y =      2.322555 mm,	Z =     29.121510 mm,
	W =    179.517423 deg,	P =     -0.141682 deg,	R =      0.001193 deg
};
P[367:"p1198"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     24.711293 mm,	Y =      2.223089 mm,	Z =     28.967973 mm,
	W =    179.550073 deg,	P =     -2.846737 deg,	R =      0.022346 deg
};
P[368:"p1200"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     18.895203 mm,	Y =      2.077267 mm,	Z =     28.554183 mm,
	W =    179.595471 deg,	P =     -5.239496 deg,	R =      0.036942 deg
};
P[369:"p1203"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     10.147944 mm,	Y =      1.824930 mm,	Z =     27.528951 mm,
	W =    179.677167 deg,	P =     -7.938118 deg,	R =      0.044585 deg
};
P[370:"p1207"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =     -1.578314 mm,	Y =      1.450996 mm,	Z =     25.673981 mm,
	W =    179.780687 deg,	P =     -9.677692 deg,	R =      0.036868 deg
};
P[371:"p1212"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -16.439815 mm,	Y =      1.039607 mm,	Z =     23.207959 mm,
	W =    179.876259 deg,	P =     -8.663274 deg,	R =      0.018639 deg
};
P[372:"p1215"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -25.495206 mm,	Y =      0.887397 mm,	Z =     21.979528 mm,
	W =    179.905278 deg,	P =     -6.656592 deg,	R =      0.010980 deg
};
P[373:"p1217"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -31.484065 mm,	Y =      0.830775 mm,	Z =     21.367103 mm,
	W =    179.916399 deg,	P =     -4.985500 deg,	R =      0.007265 deg
};
P[374:"lead_out1220"]{
   GP1:
	UF : 1, UT : 1,		CONFIG : 'F U T, 0, 0, 0',
	X =    -33.569754 mm,	Y =      0.865530 mm,	Z =     45.276279 mm,
	W =    179.916399 deg,	P =     -4.985500 deg,	R =      0.007265 deg
};
/END
