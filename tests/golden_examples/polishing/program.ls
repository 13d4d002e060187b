/PROG  POLISH
/ATTR
OWNER		= MNEDITOR;
COMMENT		= "workbench";
PROG_SIZE	= 0;
CREATE		= DATE 26-01-01  TIME 00:00:00;
MODIFIED	= DATE 26-01-01  TIME 00:00:00;
FILE_NAME	= ;
VERSION		= 0;
LINE_COUNT	= 1221;
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
   1:J P[1] 50% FINE ;  ! approach
   2:L P[2] 40mm/sec FINE ;
   3:L P[3] 40mm/sec CNT1 ;
   4:L P[4] 40mm/sec CNT1 ;
   5:L P[5] 40mm/sec CNT1 ;
   6:L P[6] 40mm/sec CNT1 ;
   7:L P[7] 40mm/sec CNT1 ;
   8:L P[8] 40mm/sec CNT1 ;
   9:L P[9] 40mm/sec CNT1 ;
  10:L P[10] 40mm/sec CNT1 ;
  11:L P[11] 40mm/sec CNT1 ;
  12:L P[12] 40mm/sec CNT1 ;
  13:L P[13] 40mm/sec CNT1 ;
  14:L P[14] 40mm/sec CNT1 ;
  15:L P[15] 40mm/sec CNT1 ;
  16:L P[16] 40mm/sec CNT1 ;
  17:L P[17] 40mm/sec CNT1 ;
  18:L P[18] 40mm/sec CNT1 ;
  19:L P[19] 40mm/sec CNT1 ;
  20:L P[20] 40mm/sec CNT1 ;
  21:L P[21] 40mm/sec CNT1 ;
  22:L P[22] 40mm/sec CNT1 ;
  23:L P[23] 40mm/sec CNT1 ;
  24:L P[24] 40mm/sec CNT1 ;
  25:L P[25] 40mm/sec CNT1 ;
  26:L P[26] 40mm/sec CNT1 ;
  27:L P[27] 40mm/sec CNT1 ;
  28:L P[28] 40mm/sec CNT1 ;
  29:L P[29] 40mm/sec CNT1 ;
  30:L P[30] 40mm/sec CNT1 ;
  31:L P[31] 40mm/sec CNT1 ;
  32:L P[32] 40mm/sec CNT1 ;
  33:L P[33] 40mm/sec CNT1 ;
  34:L P[34] 40mm/sec CNT1 ;
  35:L P[35] 40mm/sec CNT1 ;
  36:L P[36] 40mm/sec CNT1 ;
  37:L P[37] 40mm/sec CNT1 ;
  38:L P[38] 40mm/sec CNT1 ;
  39:L P[39] 40mm/sec CNT1 ;
  40:L P[40] 40mm/sec CNT1 ;
  41:L P[41] 40mm/sec CNT1 ;
  42:L P[42] 40mm/sec CNT1 ;
  43:L P[43] 40mm/sec CNT1 ;
  44:L P[44] 40mm/sec CNT1 ;
  45:L P[45] 40mm/sec CNT1 ;
  46:L P[46] 40mm/sec CNT1 ;
  47:L P[47] 40mm/sec CNT1 ;
  48:L P[48] 40mm/sec CNT1 ;
  49:L P[49] 40mm/sec CNT1 ;
  50:L P[50] 40mm/sec CNT1 ;
  51:L P[51] 40mm/sec CNT1 ;
  52:L P[52] 40mm/sec CNT1 ;
  53:L P[53] 40mm/sec CNT1 ;
  54:L P[54] 40mm/sec CNT1 ;
  55:L P[55] 40mm/sec CNT1 ;
  56:L P[56] 40mm/sec CNT1 ;
  57:L P[57] 40mm/sec CNT1 ;
  58:L P[58] 40mm/sec CNT1 ;
  59:L P[59] 40mm/sec CNT1 ;
  60:L P[60] 40mm/sec CNT1 ;
  61:L P[61] 40mm/sec CNT1 ;
  62:L P[62] 40mm/sec CNT1 ;
  63:L P[63] 40mm/sec CNT1 ;
  64:L P[64] 40mm/sec CNT1 ;
  65:L P[65] 40mm/sec CNT1 ;
  66:L P[66] 40mm/sec CNT1 ;
  67:L P[67] 40mm/sec CNT1 ;
  68:L P[68] 40mm/sec CNT1 ;
  69:L P[69] 40mm/sec CNT1 ;
  70:L P[70] 40mm/sec CNT1 ;
  71:L P[71] 40mm/sec CNT1 ;
  72:L P[72] 40mm/sec CNT1 ;
  73:L P[73] 40mm/sec CNT1 ;
  74:L P[74] 40mm/sec CNT1 ;
  75:L P[75] 40mm/sec CNT1 ;
  76:L P[76] 40mm/sec CNT1 ;
  77:L P[77] 40mm/sec CNT1 ;
  78:L P[78] 40mm/sec CNT1 ;
  79:L P[79] 40mm/sec CNT1 ;
  80:L P[80] 40mm/sec CNT1 ;
  81:L P[81] 40mm/sec CNT1 ;
  82:L P[82] 40mm/sec CNT1 ;
  83:L P[83] 40mm/sec CNT1 ;
  84:L P[84] 40mm/sec CNT1 ;
  85:L P[85] 40mm/sec CNT1 ;
  86:L P[86] 40mm/sec CNT1 ;
  87:L P[87] 40mm/sec CNT1 ;
  88:L P[88] 40mm/sec CNT1 ;
  89:L P[89] 40mm/sec CNT1 ;
  90:L P[90] 40mm/sec CNT1 ;
  91:L P[91] 40mm/sec CNT1 ;
  92:L P[92] 40mm/sec CNT1 ;
  93:L P[93] 40mm/sec CNT1 ;
  94:L P[94] 40mm/sec CNT1 ;
  95:L P[95] 40mm/sec CNT1 ;
  96:L P[96] 40mm/sec CNT1 ;
  97:L P[97] 40mm/sec CNT1 ;
  98:L P[98] 40mm/sec CNT1 ;
  99:L P[99] 40mm/sec CNT1 ;
 100:L P[100] 40mm/sec CNT1 ;
 101:L P[101] 40mm/sec CNT1 ;
 102:L P[102] 40mm/sec CNT1 ;
 103:L P[103] 40mm/sec CNT1 ;
 104:L P[104] 40mm/sec CNT1 ;
 105:L P[105] 40mm/sec CNT1 ;
 106:L P[106] 40mm/sec CNT1 ;
 107:L P[107] 40mm/sec CNT1 ;
 108:L P[108] 40mm/sec CNT1 ;
 109:L P[109] 40mm/sec CNT1 ;
 110:L P[110] 40mm/sec CNT1 ;
 111:L P[111] 40mm/sec CNT1 ;
 112:L P[112] 40mm/sec CNT1 ;
 113:L P[113] 40mm/sec CNT1 ;
 114:L P[114] 40mm/sec CNT1 ;
 115:L P[115] 40mm/sec CNT1 ;
 116:L P[116] 40mm/sec CNT1 ;
 117:L P[117] 40mm/sec CNT1 ;
 118:L P[118] 40mm/sec CNT1 ;
 119:L P[119] 40mm/sec CNT1 ;
 120:L P[120] 40mm/sec CNT1 ;
 121:L P[121] 40mm/sec CNT1 ;
 122:L P[122] 40mm/sec CNT1 ;
 123:L P[123] 40mm/sec CNT1 ;
 124:L P[124] 40mm/sec CNT1 ;
 125:L P[125] 40mm/sec CNT1 ;
 126:L P[126] 40mm/sec CNT1 ;
 127:L P[127] 40mm/sec CNT1 ;
 128:L P[128] 40mm/sec CNT1 ;
 129:L P[129] 40mm/sec CNT1 ;
 130:L P[130] 40mm/sec CNT1 ;
 131:L P[131] 40mm/sec CNT1 ;
 132:L P[132] 40mm/sec CNT1 ;
 133:L P[133] 40mm/sec CNT1 ;
 134:L P[134] 40mm/sec CNT1 ;
 135:L P[135] 40mm/sec CNT1 ;
 136:L P[136] 40mm/sec CNT1 ;
 137:L P[137] 40mm/sec CNT1 ;
 138:L P[138] 40mm/sec CNT1 ;
 139:L P[139] 40mm/sec CNT1 ;
 140:L P[140] 40mm/sec CNT1 ;
 141:L P[141] 40mm/sec CNT1 ;
 142:L P[142] 40mm/sec CNT1 ;
 143:L P[143] 40mm/sec CNT1 ;
 144:L P[144] 40mm/sec CNT1 ;
 145:L P[145] 40mm/sec CNT1 ;
 146:L P[146] 40mm/sec CNT1 ;
 147:L P[147] 40mm/sec CNT1 ;
 148:L P[148] 40mm/sec CNT1 ;
 149:L P[149] 40mm/sec CNT1 ;
 150:L P[150] 40mm/sec CNT1 ;
 151:L P[151] 40mm/sec CNT1 ;
 152:L P[152] 40mm/sec CNT1 ;
 153:L P[153] 40mm/sec CNT1 ;
 154:L P[154] 40mm/sec CNT1 ;
 155:L P[155] 40mm/sec CNT1 ;
 156:L P[156] 40mm/sec CNT1 ;
 157:L P[157] 40mm/sec CNT1 ;
 158:L P[158] 40mm/sec CNT1 ;
 159:L P[159] 40mm/sec CNT1 ;
 160:L P[160] 40mm/sec CNT1 ;
 161:L P[161] 40mm/sec CNT1 ;
 162:L P[162] 40mm/sec CNT1 ;
 163:L P[163] 40mm/sec CNT1 ;
 164:L P[164] 40mm/sec CNT1 ;
 165:L P[165] 40mm/sec CNT1 ;
 166:L P[166] 40mm/sec CNT1 ;
 167:L P[167] 40mm/sec CNT1 ;
 168:L P[168] 40mm/sec CNT1 ;
 169:L P[169] 40mm/sec CNT1 ;
 170:L P[170] 40mm/sec CNT1 ;
 171:L P[171] 40mm/sec CNT1 ;
 172:L P[172] 40mm/sec CNT1 ;
 173:L P[173] 40mm/sec CNT1 ;
 174:L P[174] 40mm/sec CNT1 ;
 175:L P[175] 40mm/sec CNT1 ;
 176:L P[176] 40mm/sec CNT1 ;
 177:L P[177] 40mm/sec CNT1 ;
 178:L P[178] 40mm/sec CNT1 ;
 179:L P[179] 40mm/sec CNT1 ;
 180:L P[180] 40mm/sec CNT1 ;
 181:L P[181] 40mm/sec CNT1 ;
 182:L P[182] 40mm/sec CNT1 ;
 183:L P[183] 40mm/sec CNT1 ;
 184:L P[184] 40mm/sec CNT1 ;
 185:L P[185] 40mm/sec CNT1 ;
 186:L P[186] 40mm/sec CNT1 ;
 187:L P[187] 40mm/sec CNT1 ;
 188:L P[188] 40mm/sec CNT1 ;
 189:L P[189] 40mm/sec CNT1 ;
 190:L P[190] 40mm/sec CNT1 ;
 191:L P[191] 40mm/sec CNT1 ;
 192:L P[192] 40mm/sec CNT1 ;
 193:L P[193] 40mm/sec CNT1 ;
 194:L P[194] 40mm/sec CNT1 ;
 195:L P[195] 40mm/sec CNT1 ;
 196:L P[196] 40mm/sec CNT1 ;
 197:L P[197] 40mm/sec CNT1 ;
 198:L P[198] 40mm/sec CNT1 ;
 199:L P[199] 40mm/sec CNT1 ;
 200:L P[200] 40mm/sec CNT1 ;
 201:L P[201] 40mm/sec CNT1 ;
 202:L P[202] 40mm/sec CNT1 ;
 203:L P[203] 40mm/sec CNT1 ;
 204:L P[204] 40mm/sec CNT1 ;
 205:L P[205] 40mm/sec CNT1 ;
 206:L P[206] 40mm/sec CNT1 ;
 207:L P[207] 40mm/sec CNT1 ;
 208:L P[208] 40mm/sec CNT1 ;
 209:L P[209] 40mm/sec CNT1 ;
 210:L P[210] 40mm/sec CNT1 ;
 211:L P[211] 40mm/sec CNT1 ;
 212:L P[212] 40mm/sec CNT1 ;
 213:L P[213] 40mm/sec CNT1 ;
 214:L P[214] 40mm/sec CNT1 ;
 215:L P[215] 40mm/sec CNT1 ;
 216:L P[216] 40mm/sec CNT1 ;
 217:L P[217] 40mm/sec CNT1 ;
 218:L P[218] 40mm/sec CNT1 ;
 219:L P[219] 40mm/sec CNT1 ;
 220:L P[220] 40mm/sec CNT1 ;
 221:L P[221] 40mm/sec CNT1 ;
 222:L P[222] 40mm/sec CNT1 ;
 223:L P[223] 40mm/sec CNT1 ;
 224:L P[224] 40mm/sec CNT1 ;
 225:L P[225] 40mm/sec CNT1 ;
 226:L P[226] 40mm/sec CNT1 ;
 227:L P[227] 40mm/sec CNT1 ;
 228:L P[228] 40mm/sec CNT1 ;
 229:L P[229] 40mm/sec CNT1 ;
 230:L P[230] 40mm/sec CNT1 ;
 231:L P[231] 40mm/sec CNT1 ;
 232:L P[232] 40mm/sec CNT1 ;
 233:L P[233] 40mm/sec CNT1 ;
 234:L P[234] 40mm/sec CNT1 ;
 235:L P[235] 40mm/sec CNT1 ;
 236:L P[236] 40mm/sec CNT1 ;
 237:L P[237] 40mm/sec CNT1 ;
 238:L P[238] 40mm/sec CNT1 ;
 239:L P[239] 40mm/sec CNT1 ;
 240:L P[240] 40mm/sec CNT1 ;
 241:L P[241] 40mm/sec CNT1 ;
 242:L P[242] 40mm/sec CNT1 ;
 243:L P[243] 40mm/sec CNT1 ;
 244:L P[244] 40mm/sec CNT1 ;
 245:L P[245] 40mm/sec CNT1 ;
 246:L P[246] 40mm/sec CNT1 ;
 247:L P[247] 40mm/sec CNT1 ;
 248:L P[248] 40mm/sec CNT1 ;
 249:L P[249] 40mm/sec CNT1 ;
 250:L P[250] 40mm/sec CNT1 ;
 251:L P[251] 40mm/sec CNT1 ;
 252:L P[252] 40mm/sec CNT1 ;
 253:L P[253] 40mm/sec CNT1 ;
 254:L P[254] 40mm/sec CNT1 ;
 255:L P[255] 40mm/sec CNT1 ;
 256:L P[256] 40mm/sec CNT1 ;
 257:L P[257] 40mm/sec CNT1 ;
 258:L P[258] 40mm/sec CNT1 ;
 259:L P[259] 40mm/sec CNT1 ;
 260:L P[260] 40mm/sec CNT1 ;
 261:L P[261] 40mm/sec CNT1 ;
 262:L P[262] 40mm/sec CNT1 ;
 263:L P[263] 40mm/sec CNT1 ;
 264:L P[264] 40mm/sec CNT1 ;
 265:L P[265] 40mm/sec CNT1 ;
 266:L P[266] 40mm/sec CNT1 ;
 267:L P[267] 40mm/sec CNT1 ;
 268:L P[268] 40mm/sec CNT1 ;
 269:L P[269] 40mm/sec CNT1 ;
 270:L P[270] 40mm/sec CNT1 ;
 271:L P[271] 40mm/sec CNT1 ;
 272:L P[272] 40mm/sec CNT1 ;
 273:L P[273] 40mm/sec CNT1 ;
 274:L P[274] 40mm/sec CNT1 ;
 275:L P[275] 40mm/sec CNT1 ;
 276:L P[276] 40mm/sec CNT1 ;
 277:L P[277] 40mm/sec CNT1 ;
 278:L P[278] 40mm/sec CNT1 ;
 279:L P[279] 40mm/sec CNT1 ;
 280:L P[280] 40mm/sec CNT1 ;
 281:L P[281] 40mm/sec CNT1 ;
 282:L P[282] 40mm/sec CNT1 ;
 283:L P[283] 40mm/sec CNT1 ;
 284:L P[284] 40mm/sec CNT1 ;
 285:L P[285] 40mm/sec CNT1 ;
 286:L P[286] 40mm/sec CNT1 ;
 287:L P[287] 40mm/sec CNT1 ;
 288:L P[288] 40mm/sec CNT1 ;
 289:L P[289] 40mm/sec CNT1 ;
 290:L P[290] 40mm/sec CNT1 ;
 291:L P[291] 40mm/sec CNT1 ;
 292:L P[292] 40mm/sec CNT1 ;
 293:L P[293] 40mm/sec CNT1 ;
 294:L P[294] 40mm/sec CNT1 ;
 295:L P[295] 40mm/sec CNT1 ;
 296:L P[296] 40mm/sec CNT1 ;
 297:L P[297] 40mm/sec CNT1 ;
 298:L P[298] 40mm/sec CNT1 ;
 299:L P[299] 40mm/sec CNT1 ;
 300:L P[300] 40mm/sec CNT1 ;
 301:L P[301] 40mm/sec CNT1 ;
 302:L P[302] 40mm/sec CNT1 ;
 303:L P[303] 40mm/sec CNT1 ;
 304:L P[304] 40mm/sec CNT1 ;
 305:L P[305] 40mm/sec CNT1 ;
 306:L P[306] 40mm/sec CNT1 ;
 307:L P[307] 40mm/sec CNT1 ;
 308:L P[308] 40mm/sec CNT1 ;
 309:L P[309] 40mm/sec CNT1 ;
 310:L P[310] 40mm/sec CNT1 ;
 311:L P[311] 40mm/sec CNT1 ;
 312:L P[312] 40mm/sec CNT1 ;
 313:L P[313] 40mm/sec CNT1 ;
 314:L P[314] 40mm/sec CNT1 ;
 315:L P[315] 40mm/sec CNT1 ;
 316:L P[316] 40mm/sec CNT1 ;
 317:L P[317] 40mm/sec CNT1 ;
 318:L P[318] 40mm/sec CNT1 ;
 319:L P[319] 40mm/sec CNT1 ;
 320:L P[320] 40mm/sec CNT1 ;
 321:L P[321] 40mm/sec CNT1 ;
 322:L P[322] 40mm/sec CNT1 ;
 323:L P[323] 40mm/sec CNT1 ;
 324:L P[324] 40mm/sec CNT1 ;
 325:L P[325] 40mm/sec CNT1 ;
 326:L P[326] 40mm/sec CNT1 ;
 327:L P[327] 40mm/sec CNT1 ;
 328:L P[328] 40mm/sec CNT1 ;
 329:L P[329] 40mm/sec CNT1 ;
 330:L P[330] 40mm/sec CNT1 ;
 331:L P[331] 40mm/sec CNT1 ;
 332:L P[332] 40mm/sec CNT1 ;
 333:L P[333] 40mm/sec CNT1 ;
 334:L P[334] 40mm/sec CNT1 ;
 335:L P[335] 40mm/sec CNT1 ;
 336:L P[336] 40mm/sec CNT1 ;
 337:L P[337] 40mm/sec CNT1 ;
 338:L P[338] 40mm/sec CNT1 ;
 339:L P[339] 40mm/sec CNT1 ;
 340:L P[340] 40mm/sec CNT1 ;
 341:L P[341] 40mm/sec CNT1 ;
 342:L P[342] 40mm/sec CNT1 ;
 343:L P[343] 40mm/sec CNT1 ;
 344:L P[344] 40mm/sec CNT1 ;
 345:L P[345] 40mm/sec CNT1 ;
 346:L P[346] 40mm/sec CNT1 ;
 347:L P[347] 40mm/sec CNT1 ;
 348:L P[348] 40mm/sec CNT1 ;
 349:L P[349] 40mm/sec CNT1 ;
 350:L P[350] 40mm/sec CNT1 ;
 351:L P[351] 40mm/sec CNT1 ;
 352:L P[352] 40mm/sec CNT1 ;
 353:L P[353] 40mm/sec CNT1 ;
 354:L P[354] 40mm/sec CNT1 ;
 355:L P[355] 40mm/sec CNT1 ;
 356:L P[356] 40mm/sec CNT1 ;
 357:L P[357] 40mm/sec CNT1 ;
 358:L P[358] 40mm/sec CNT1 ;
 359:L P[359] 40mm/sec CNT1 ;
 360:L P[360] 40mm/sec CNT1 ;
 361:L P[361] 40mm/sec CNT1 ;
 362:L P[362] 40mm/sec CNT1 ;
 363:L P[363] 40mm/sec CNT1 ;
 364:L P[364] 40mm/sec CNT1 ;
 365:L P[365] 40mm/sec CNT1 ;
 366:L P[366] 40mm/sec CNT1 ;
 367:L P[367] 40mm/sec CNT1 ;
 368:L P[368] 40mm/sec CNT1 ;
 369:L P[369] 40mm/sec CNT1 ;
 370:L P[370] 40mm/sec CNT1 ;
 371:L P[371] 40mm/sec CNT1 ;
 372:L P[372] 40mm/sec CNT1 ;
 373:L P[373] 40mm/sec CNT1 ;
 374:L P[374] 40mm/sec CNT1 ;
 375:L P[375] 40mm/sec CNT1 ;
 376:L P[376] 40mm/sec CNT1 ;
 377:L P[377] 40mm/sec CNT1 ;
 378:L P[378] 40mm/sec CNT1 ;
 379:L P[379] 40mm/sec CNT1 ;
 380:L P[380] 40mm/sec CNT1 ;
 381:L P[381] 40mm/sec CNT1 ;
 382:L P[382] 40mm/sec CNT1 ;
 383:L P[383] 40mm/sec CNT1 ;
 384:L P[384] 40mm/sec CNT1 ;
 385:L P[385] 40mm/sec CNT1 ;
 386:L P[386] 40mm/sec CNT1 ;
 387:L P[387] 40mm/sec CNT1 ;
 388:L P[388] 40mm/sec CNT1 ;
 389:L P[389] 40mm/sec CNT1 ;
 390:L P[390] 40mm/sec CNT1 ;
 391:L P[391] 40mm/sec CNT1 ;
 392:L P[392] 40mm/sec CNT1 ;
 393:L P[393] 40mm/sec CNT1 ;
 394:L P[394] 40mm/sec CNT1 ;
 395:L P[395] 40mm/sec CNT1 ;
 396:L P[396] 40mm/sec CNT1 ;
 397:L P[397] 40mm/sec CNT1 ;
 398:L P[398] 40mm/sec CNT1 ;
 399:L P[399] 40mm/sec CNT1 ;
 400:L P[400] 40mm/sec CNT1 ;
 401:L P[401] 40mm/sec CNT1 ;
 402:L P[402] 40mm/sec CNT1 ;
 403:L P[403] 40mm/sec CNT1 ;
 404:L P[404] 40mm/sec CNT1 ;
 405:L P[405] 40mm/sec CNT1 ;
 406:L P[406] 40mm/sec CNT1 ;
 407:L P[407] 40mm/sec CNT1 ;
 408:L P[408] 40mm/sec CNT1 ;
 409:L P[409] 40mm/sec CNT1 ;
 410:L P[410] 40mm/sec CNT1 ;
 411:L P[411] 40mm/sec CNT1 ;
 412:L P[412] 40mm/sec CNT1 ;
 413:L P[413] 40mm/sec CNT1 ;
 414:L P[414] 40mm/sec CNT1 ;
 415:L P[415] 40mm/sec CNT1 ;
 416:L P[416] 40mm/sec CNT1 ;
 417:L P[417] 40mm/sec CNT1 ;
 418:L P[418] 40mm/sec CNT1 ;
 419:L P[419] 40mm/sec CNT1 ;
 420:L P[420] 40mm/sec CNT1 ;
 421:L P[421] 40mm/sec CNT1 ;
 422:L P[422] 40mm/sec CNT1 ;
 423:L P[423] 40mm/sec CNT1 ;
 424:L P[424] 40mm/sec CNT1 ;
 425:L P[425] 40mm/sec CNT1 ;
 426:L P[426] 40mm/sec CNT1 ;
 427:L P[427] 40mm/sec CNT1 ;
 428:L P[428] 40mm/sec CNT1 ;
 429:L P[429] 40mm/sec CNT1 ;
 430:L P[430] 40mm/sec CNT1 ;
 431:L P[431] 40mm/sec CNT1 ;
 432:L P[432] 40mm/sec CNT1 ;
 433:L P[433] 40mm/sec CNT1 ;
 434:L P[434] 40mm/sec CNT1 ;
 435:L P[435] 40mm/sec CNT1 ;
 436:L P[436] 40mm/sec CNT1 ;
 437:L P[437] 40mm/sec CNT1 ;
 438:L P[438] 40mm/sec CNT1 ;
 439:L P[439] 40mm/sec CNT1 ;
 440:L P[440] 40mm/sec CNT1 ;
 441:L P[441] 40mm/sec CNT1 ;
 442:L P[442] 40mm/sec CNT1 ;
 443:L P[443] 40mm/sec CNT1 ;
 444:L P[444] 40mm/sec CNT1 ;
 445:L P[445] 40mm/sec CNT1 ;
 446:L P[446] 40mm/sec CNT1 ;
 447:L P[447] 40mm/sec CNT1 ;
 448:L P[448] 40mm/sec CNT1 ;
 449:L P[449] 40mm/sec CNT1 ;
 450:L P[450] 40mm/sec CNT1 ;
 451:L P[451] 40mm/sec CNT1 ;
 452:L P[452] 40mm/sec CNT1 ;
 453:L P[453] 40mm/sec CNT1 ;
 454:L P[454] 40mm/sec CNT1 ;
 455:L P[455] 40mm/sec CNT1 ;
 456:L P[456] 40mm/sec CNT1 ;
 457:L P[457] 40mm/sec CNT1 ;
 458:L P[458] 40mm/sec CNT1 ;
 459:L P[459] 40mm/sec CNT1 ;
 460:L P[460] 40mm/sec CNT1 ;
 461:L P[461] 40mm/sec CNT1 ;
 462:L P[462] 40mm/sec CNT1 ;
 463:L P[463] 40mm/sec CNT1 ;
 464:L P[464] 40mm/sec CNT1 ;
 465:L P[465] 40mm/sec CNT1 ;
 466:L P[466] 40mm/sec CNT1 ;
 467:L P[467] 40mm/sec CNT1 ;
 468:L P[468] 40mm/sec CNT1 ;
 469:L P[469] 40mm/sec CNT1 ;
 470:L P[470] 40mm/sec CNT1 ;
 471:L P[471] 40mm/sec CNT1 ;
 472:L P[472] 40mm/sec CNT1 ;
 473:L P[473] 40mm/sec CNT1 ;
 474:L P[474] 40mm/sec CNT1 ;
 475:L P[475] 40mm/sec CNT1 ;
 476:L P[476] 40mm/sec CNT1 ;
 477:L P[477] 40mm/sec CNT1 ;
 478:L P[478] 40mm/sec CNT1 ;
 479:L P[479] 40mm/sec CNT1 ;
 480:L P[480] 40mm/sec CNT1 ;
 481:L P[481] 40mm/sec CNT1 ;
 482:L P[482] 40mm/sec CNT1 ;
 483:L P[483] 40mm/sec CNT1 ;
 484:L P[484] 40mm/sec CNT1 ;
 485:L P[485] 40mm/sec CNT1 ;
 486:L P[486] 40mm/sec CNT1 ;
 487:L P[487] 40mm/sec CNT1 ;
 488:L P[488] 40mm/sec CNT1 ;
 489:L P[489] 40mm/sec CNT1 ;
 490:L P[490] 40mm/sec CNT1 ;
 491:L P[491] 40mm/sec CNT1 ;
 492:L P[492] 40mm/sec CNT1 ;
 493:L P[493] 40mm/sec CNT1 ;
 494:L P[494] 40mm/sec CNT1 ;
 495:L P[495] 40mm/sec CNT1 ;
 496:L P[496] 40mm/sec CNT1 ;
 497:L P[497] 40mm/sec CNT1 ;
 498:L P[498] 40mm/sec CNT1 ;
 499:L P[499] 40mm/sec CNT1 ;
 500:L P[500] 40mm/sec CNT1 ;
 501:L P[501] 40mm/sec CNT1 ;
 502:L P[502] 40mm/sec CNT1 ;
 503:L P[503] 40mm/sec CNT1 ;
 504:L P[504] 40mm/sec CNT1 ;
 505:L P[505] 40mm/sec CNT1 ;
 506:L P[506] 40mm/sec CNT1 ;
 507:L P[507] 40mm/sec CNT1 ;
 508:L P[508] 40mm/sec CNT1 ;
 509:L P[509] 40mm/sec CNT1 ;
 510:L P[510] 40mm/sec CNT1 ;
 511:L P[511] 40mm/sec CNT1 ;
 512:L P[512] 40mm/sec CNT1 ;
 513:L P[513] 40mm/sec CNT1 ;
 514:L P[514] 40mm/sec CNT1 ;
 515:L P[515] 40mm/sec CNT1 ;
 516:L P[516] 40mm/sec CNT1 ;
 517:L P[517] 40mm/sec CNT1 ;
 518:L P[518] 40mm/sec CNT1 ;
 519:L P[519] 40mm/sec CNT1 ;
 520:L P[520] 40mm/sec CNT1 ;
 521:L P[521] 40mm/sec CNT1 ;
 522:L P[522] 40mm/sec CNT1 ;
 523:L P[523] 40mm/sec CNT1 ;
 524:L P[524] 40mm/sec CNT1 ;
 525:L P[525] 40mm/sec CNT1 ;
 526:L P[526] 40mm/sec CNT1 ;
 527:L P[527] 40mm/sec CNT1 ;
 528:L P[528] 40mm/sec CNT1 ;
 529:L P[529] 40mm/sec CNT1 ;
 530:L P[530] 40mm/sec CNT1 ;
 531:L P[531] 40mm/sec CNT1 ;
 532:L P[532] 40mm/sec CNT1 ;
 533:L P[533] 40mm/sec CNT1 ;
 534:L P[534] 40mm/sec CNT1 ;
 535:L P[535] 40mm/sec CNT1 ;
 536:L P[536] 40mm/sec CNT1 ;
 537:L P[537] 40mm/sec CNT1 ;
 538:L P[538] 40mm/sec CNT1 ;
 539:L P[539] 40mm/sec CNT1 ;
 540:L P[540] 40mm/sec CNT1 ;
 541:L P[541] 40mm/sec CNT1 ;
 542:L P[542] 40mm/sec CNT1 ;
 543:L P[543] 40mm/sec CNT1 ;
 544:L P[544] 40mm/sec CNT1 ;
 545:L P[545] 40mm/sec CNT1 ;
 546:L P[546] 40mm/sec CNT1 ;
 547:L P[547] 40mm/sec CNT1 ;
 548:L P[548] 40mm/sec CNT1 ;
 549:L P[549] 40mm/sec CNT1 ;
 550:L P[550] 40mm/sec CNT1 ;
 551:L P[551] 40mm/sec CNT1 ;
 552:L P[552] 40mm/sec CNT1 ;
 553:L P[553] 40mm/sec CNT1 ;
 554:L P[554] 40mm/sec CNT1 ;
 555:L P[555] 40mm/sec CNT1 ;
 556:L P[556] 40mm/sec CNT1 ;
 557:L P[557] 40mm/sec CNT1 ;
 558:L P[558] 40mm/sec CNT1 ;
 559:L P[559] 40mm/sec CNT1 ;
 560:L P[560] 40mm/sec CNT1 ;
 561:L P[561] 40mm/sec CNT1 ;
 562:L P[562] 40mm/sec CNT1 ;
 563:L P[563] 40mm/sec CNT1 ;
 564:L P[564] 40mm/sec CNT1 ;
 565:L P[565] 40mm/sec CNT1 ;
 566:L P[566] 40mm/sec CNT1 ;
 567:L P[567] 40mm/sec CNT1 ;
 568:L P[568] 40mm/sec CNT1 ;
 569:L P[569] 40mm/sec CNT1 ;
 570:L P[570] 40mm/sec CNT1 ;
 571:L P[571] 40mm/sec CNT1 ;
 572:L P[572] 40mm/sec CNT1 ;
 573:L P[573] 40mm/sec CNT1 ;
 574:L P[574] 40mm/sec CNT1 ;
 575:L P[575] 40mm/sec CNT1 ;
 576:L P[576] 40mm/sec CNT1 ;
 577:L P[577] 40mm/sec CNT1 ;
 578:L P[578] 40mm/sec CNT1 ;
 579:L P[579] 40mm/sec CNT1 ;
 580:L P[580] 40mm/sec CNT1 ;
 581:L P[581] 40mm/sec CNT1 ;
 582:L P[582] 40mm/sec CNT1 ;
 583:L P[583] 40mm/sec CNT1 ;
 584:L P[584] 40mm/sec CNT1 ;
 585:L P[585] 40mm/sec CNT1 ;
 586:L P[586] 40mm/sec CNT1 ;
 587:L P[587] 40mm/sec CNT1 ;
 588:L P[588] 40mm/sec CNT1 ;
 589:L P[589] 40mm/sec CNT1 ;
 590:L P[590] 40mm/sec CNT1 ;
 591:L P[591] 40mm/sec CNT1 ;
 592:L P[592] 40mm/sec CNT1 ;
 593:L P[593] 40mm/sec CNT1 ;
 594:L P[594] 40mm/sec CNT1 ;
 595:L P[595] 40mm/sec CNT1 ;
 596:L P[596] 40mm/sec CNT1 ;
 597:L P[597] 40mm/sec CNT1 ;
 598:L P[598] 40mm/sec CNT1 ;
 599:L P[599] 40mm/sec CNT1 ;
 600:L P[600] 40mm/sec CNT1 ;
 601:L P[601] 40mm/sec CNT1 ;
 602:L P[602] 40mm/sec CNT1 ;
 603:L P[603] 40mm/sec CNT1 ;
 604:L P[604] 40mm/sec CNT1 ;
 605:L P[605] 40mm/sec CNT1 ;
 606:L P[606] 40mm/sec CNT1 ;
 607:L P[607] 40mm/sec CNT1 ;
 608:L P[608] 40mm/sec CNT1 ;
 609:L P[609] 40mm/sec CNT1 ;
 610:L P[610] 40mm/sec CNT1 ;
 611:L P[611] 40mm/sec CNT1 ;
 612:L P[612] 40mm/sec CNT1 ;
 613:L P[613] 40mm/sec CNT1 ;
 614:L P[614] 40mm/sec CNT1 ;
 615:L P[615] 40mm/sec CNT1 ;
 616:L P[616] 40mm/sec CNT1 ;
 617:L P[617] 40mm/sec CNT1 ;
 618:L P[618] 40mm/sec CNT1 ;
 619:L P[619] 40mm/sec CNT1 ;
 620:L P[620] 40mm/sec CNT1 ;
 621:L P[621] 40mm/sec CNT1 ;
 622:L P[622] 40mm/sec CNT1 ;
 623:L P[623] 40mm/sec CNT1 ;
 624:L P[624] 40mm/sec CNT1 ;
 625:L P[625] 40mm/sec CNT1 ;
 626:L P[626] 40mm/sec CNT1 ;
 627:L P[627] 40mm/sec CNT1 ;
 628:L P[628] 40mm/sec CNT1 ;
 629:L P[629] 40mm/sec CNT1 ;
 630:L P[630] 40mm/sec CNT1 ;
 631:L P[631] 40mm/sec CNT1 ;
 632:L P[632] 40mm/sec CNT1 ;
 633:L P[633] 40mm/sec CNT1 ;
 634:L P[634] 40mm/sec CNT1 ;
 635:L P[635] 40mm/sec CNT1 ;
 636:L P[636] 40mm/sec CNT1 ;
 637:L P[637] 40mm/sec CNT1 ;
 638:L P[638] 40mm/sec CNT1 ;
 639:L P[639] 40mm/sec CNT1 ;
 640:L P[640] 40mm/sec CNT1 ;
 641:L P[641] 40mm/sec CNT1 ;
 642:L P[642] 40mm/sec CNT1 ;
 643:L P[643] 40mm/sec CNT1 ;
 644:L P[644] 40mm/sec CNT1 ;
 645:L P[645] 40mm/sec CNT1 ;
 646:L P[646] 40mm/sec CNT1 ;
 647:L P[647] 40mm/sec CNT1 ;
 648:L P[648] 40mm/sec CNT1 ;
 649:L P[649] 40mm/sec CNT1 ;
 650:L P[650] 40mm/sec CNT1 ;
 651:L P[651] 40mm/sec CNT1 ;
 652:L P[652] 40mm/sec CNT1 ;
 653:L P[653] 40mm/sec CNT1 ;
 654:L P[654] 40mm/sec CNT1 ;
 655:L P[655] 40mm/sec CNT1 ;
 656:L P[656] 40mm/sec CNT1 ;
 657:L P[657] 40mm/sec CNT1 ;
 658:L P[658] 40mm/sec CNT1 ;
 659:L P[659] 40mm/sec CNT1 ;
 660:L P[660] 40mm/sec CNT1 ;
 661:L P[661] 40mm/sec CNT1 ;
 662:L P[662] 40mm/sec CNT1 ;
 663:L P[663] 40mm/sec CNT1 ;
 664:L P[664] 40mm/sec CNT1 ;
 665:L P[665] 40mm/sec CNT1 ;
 666:L P[666] 40mm/sec CNT1 ;
 667:L P[667] 40mm/sec CNT1 ;
 668:L P[668] 40mm/sec CNT1 ;
 669:L P[669] 40mm/sec CNT1 ;
 670:L P[670] 40mm/sec CNT1 ;
 671:L P[671] 40mm/sec CNT1 ;
 672:L P[672] 40mm/sec CNT1 ;
 673:L P[673] 40mm/sec CNT1 ;
 674:L P[674] 40mm/sec CNT1 ;
 675:L P[675] 40mm/sec CNT1 ;
 676:L P[676] 40mm/sec CNT1 ;
 677:L P[677] 40mm/sec CNT1 ;
 678:L P[678] 40mm/sec CNT1 ;
 679:L P[679] 40mm/sec CNT1 ;
 680:L P[680] 40mm/sec CNT1 ;
 681:L P[681] 40mm/sec CNT1 ;
 682:L P[682] 40mm/sec CNT1 ;
 683:L P[683] 40mm/sec CNT1 ;
 684:L P[684] 40mm/sec CNT1 ;
 685:L P[685] 40mm/sec CNT1 ;
 686:L P[686] 40mm/sec CNT1 ;
 687:L P[687] 40mm/sec CNT1 ;
 688:L P[688] 40mm/sec CNT1 ;
 689:L P[689] 40mm/sec CNT1 ;
 690:L P[690] 40mm/sec CNT1 ;
 691:L P[691] 40mm/sec CNT1 ;
 692:L P[692] 40mm/sec CNT1 ;
 693:L P[693] 40mm/sec CNT1 ;
 694:L P[694] 40mm/sec CNT1 ;
 695:L P[695] 40mm/sec CNT1 ;
 696:L P[696] 40mm/sec CNT1 ;
 697:L P[697] 40mm/sec CNT1 ;
 698:L P[698] 40mm/sec CNT1 ;
 699:L P[699] 40mm/sec CNT1 ;
 700:L P[700] 40mm/sec CNT1 ;
 701:L P[701] 40mm/sec CNT1 ;
 702:L P[702] 40mm/sec CNT1 ;
 703:L P[703] 40mm/sec CNT1 ;
 704:L P[704] 40mm/sec CNT1 ;
 705:L P[705] 40mm/sec CNT1 ;
 706:L P[706] 40mm/sec CNT1 ;
 707:L P[707] 40mm/sec CNT1 ;
 708:L P[708] 40mm/sec CNT1 ;
 709:L P[709] 40mm/sec CNT1 ;
 710:L P[710] 40mm/sec CNT1 ;
 711:L P[711] 40mm/sec CNT1 ;
 712:L P[712] 40mm/sec CNT1 ;
 713:L P[713] 40mm/sec CNT1 ;
 714:L P[714] 40mm/sec CNT1 ;
 715:L P[715] 40mm/sec CNT1 ;
 716:L P[716] 40mm/sec CNT1 ;
 717:L P[717] 40mm/sec CNT1 ;
 718:L P[718] 40mm/sec CNT1 ;
 719:L P[719] 40mm/sec CNT1 ;
 720:L P[720] 40mm/sec CNT1 ;
 721:L P[721] 40mm/sec CNT1 ;
 722:L P[722] 40mm/sec CNT1 ;
 723:L P[723] 40mm/sec CNT1 ;
 724:L P[724] 40mm/sec CNT1 ;
 725:L P[725] 40mm/sec CNT1 ;
 726:L P[726] 40mm/sec CNT1 ;
 727:L P[727] 40mm/sec CNT1 ;
 728:L P[728] 40mm/sec CNT1 ;
 729:L P[729] 40mm/sec CNT1 ;
 730:L P[730] 40mm/sec CNT1 ;
 731:L P[731] 40mm/sec CNT1 ;
 732:L P[732] 40mm/sec CNT1 ;
 733:L P[733] 40mm/sec CNT1 ;
 734:L P[734] 40mm/sec CNT1 ;
 735:L P[735] 40mm/sec CNT1 ;
 736:L P[736] 40mm/sec CNT1 ;
 737:L P[737] 40mm/sec CNT1 ;
 738:L P[738] 40mm/sec CNT1 ;
 739:L P[739] 40mm/sec CNT1 ;
 740:L P[740] 40mm/sec CNT1 ;
 741:L P[741] 40mm/sec CNT1 ;
 742:L P[742] 40mm/sec CNT1 ;
 743:L P[743] 40mm/sec CNT1 ;
 744:L P[744] 40mm/sec CNT1 ;
 745:L P[745] 40mm/sec CNT1 ;
 746:L P[746] 40mm/sec CNT1 ;
 747:L P[747] 40mm/sec CNT1 ;
 748:L P[748] 40mm/sec CNT1 ;
 749:L P[749] 40mm/sec CNT1 ;
 750:L P[750] 40mm/sec CNT1 ;
 751:L P[751] 40mm/sec CNT1 ;
 752:L P[752] 40mm/sec CNT1 ;
 753:L P[753] 40mm/sec CNT1 ;
 754:L P[754] 40mm/sec CNT1 ;
 755:L P[755] 40mm/sec CNT1 ;
 756:L P[756] 40mm/sec CNT1 ;
 757:L P[757] 40mm/sec CNT1 ;
 758:L P[758] 40mm/sec CNT1 ;
 759:L P[759] 40mm/sec CNT1 ;
 760:L P[760] 40mm/sec CNT1 ;
 761:L P[761] 40mm/sec CNT1 ;
 762:L P[762] 40mm/sec CNT1 ;
 763:L P[763] 40mm/sec CNT1 ;
 764:L P[764] 40mm/sec CNT1 ;
 765:L P[765] 40mm/sec CNT1 ;
 766:L P[766] 40mm/sec CNT1 ;
 767:L P[767] 40mm/sec CNT1 ;
 768:L P[768] 40mm/sec CNT1 ;
 769:L P[769] 40mm/sec CNT1 ;
 770:L P[770] 40mm/sec CNT1 ;
 771:L P[771] 40mm/sec CNT1 ;
 772:L P[772] 40mm/sec CNT1 ;
 773:L P[773] 40mm/sec CNT1 ;
 774:L P[774] 40mm/sec CNT1 ;
 775:L P[775] 40mm/sec CNT1 ;
 776:L P[776] 40mm/sec CNT1 ;
 777:L P[777] 40mm/sec CNT1 ;
 778:L P[778] 40mm/sec CNT1 ;
 779:L P[779] 40mm/sec CNT1 ;
 780:L P[780] 40mm/sec CNT1 ;
 781:L P[781] 40mm/sec CNT1 ;
 782:L P[782] 40mm/sec CNT1 ;
 783:L P[783] 40mm/sec CNT1 ;
 784:L P[784] 40mm/sec CNT1 ;
 785:L P[785] 40mm/sec CNT1 ;
 786:L P[786] 40mm/sec CNT1 ;
 787:L P[787] 40mm/sec CNT1 ;
 788:L P[788] 40mm/sec CNT1 ;
 789:L P[789] 40mm/sec CNT1 ;
 790:L P[790] 40mm/sec CNT1 ;
 791:L P[791] 40mm/sec CNT1 ;
 792:L P[792] 40mm/sec CNT1 ;
 793:L P[793] 40mm/sec CNT1 ;
 794:L P[794] 40mm/sec CNT1 ;
 795:L P[795] 40mm/sec CNT1 ;
 796:L P[796] 40mm/sec CNT1 ;
 797:L P[797] 40mm/sec CNT1 ;
 798:L P[798] 40mm/sec CNT1 ;
 799:L P[799] 40mm/sec CNT1 ;
 800:L P[800] 40mm/sec CNT1 ;
 801:L P[801] 40mm/sec CNT1 ;
 802:L P[802] 40mm/sec CNT1 ;
 803:L P[803] 40mm/sec CNT1 ;
 804:L P[804] 40mm/sec CNT1 ;
 805:L P[805] 40mm/sec CNT1 ;
 806:L P[806] 40mm/sec CNT1 ;
 807:L P[807] 40mm/sec CNT1 ;
 808:L P[808] 40mm/sec CNT1 ;
 809:L P[809] 40mm/sec CNT1 ;
 810:L P[810] 40mm/sec CNT1 ;
 811:L P[811] 40mm/sec CNT1 ;
 812:L P[812] 40mm/sec CNT1 ;
 813:L P[813] 40mm/sec CNT1 ;
 814:L P[814] 40mm/sec CNT1 ;
 815:L P[815] 40mm/sec CNT1 ;
 816:L P[816] 40mm/sec CNT1 ;
 817:L P[817] 40mm/sec CNT1 ;
 818:L P[818] 40mm/sec CNT1 ;
 819:L P[819] 40mm/sec CNT1 ;
 820:L P[820] 40mm/sec CNT1 ;
 821:L P[821] 40mm/sec CNT1 ;
 822:L P[822] 40mm/sec CNT1 ;
 823:L P[823] 40mm/sec CNT1 ;
 824:L P[824] 40mm/sec CNT1 ;
 825:L P[825] 40mm/sec CNT1 ;
 826:L P[826] 40mm/sec CNT1 ;
 827:L P[827] 40mm/sec CNT1 ;
 828:L P[828] 40mm/sec CNT1 ;
 829:L P[829] 40mm/sec CNT1 ;
 830:L P[830] 40mm/sec CNT1 ;
 831:L P[831] 40mm/sec CNT1 ;
 832:L P[832] 40mm/sec CNT1 ;
 833:L P[833] 40mm/sec CNT1 ;
 834:L P[834] 40mm/sec CNT1 ;
 835:L P[835] 40mm/sec CNT1 ;
 836:L P[836] 40mm/sec CNT1 ;
 837:L P[837] 40mm/sec CNT1 ;
 838:L P[838] 40mm/sec CNT1 ;
 839:L P[839] 40mm/sec CNT1 ;
 840:L P[840] 40mm/sec CNT1 ;
 841:L P[841] 40mm/sec CNT1 ;
 842:L P[842] 40mm/sec CNT1 ;
 843:L P[843] 40mm/sec CNT1 ;
 844:L P[844] 40mm/sec CNT1 ;
 845:L P[845] 40mm/sec CNT1 ;
 846:L P[846] 40mm/sec CNT1 ;
 847:L P[847] 40mm/sec CNT1 ;
 848:L P[848] 40mm/sec CNT1 ;
 849:L P[849] 40mm/sec CNT1 ;
 850:L P[850] 40mm/sec CNT1 ;
 851:L P[851] 40mm/sec CNT1 ;
 852:L P[852] 40mm/sec CNT1 ;
 853:L P[853] 40mm/sec CNT1 ;
 854:L P[854] 40mm/sec CNT1 ;
 855:L P[855] 40mm/sec CNT1 ;
 856:L P[856] 40mm/sec CNT1 ;
 857:L P[857] 40mm/sec CNT1 ;
 858:L P[858] 40mm/sec CNT1 ;
 859:L P[859] 40mm/sec CNT1 ;
 860:L P[860] 40mm/sec CNT1 ;
 861:L P[861] 40mm/sec CNT1 ;
 862:L P[862] 40mm/sec CNT1 ;
 863:L P[863] 40mm/sec CNT1 ;
 864:L P[864] 40mm/sec CNT1 ;
 865:L P[865] 40mm/sec CNT1 ;
 866:L P[866] 40mm/sec CNT1 ;
 867:L P[867] 40mm/sec CNT1 ;
 868:L P[868] 40mm/sec CNT1 ;
 869:L P[869] 40mm/sec CNT1 ;
 870:L P[870] 40mm/sec CNT1 ;
 871:L P[871] 40mm/sec CNT1 ;
 872:L P[872] 40mm/sec CNT1 ;
 873:L P[873] 40mm/sec CNT1 ;
 874:L P[874] 40mm/sec CNT1 ;
 875:L P[875] 40mm/sec CNT1 ;
 876:L P[876] 40mm/sec CNT1 ;
 877:L P[877] 40mm/sec CNT1 ;
 878:L P[878] 40mm/sec CNT1 ;
 879:L P[879] 40mm/sec CNT1 ;
 880:L P[880] 40mm/sec CNT1 ;
 881:L P[881] 40mm/sec CNT1 ;
 882:L P[882] 40mm/sec CNT1 ;
 883:L P[883] 40mm/sec CNT1 ;
 884:L P[884] 40mm/sec CNT1 ;
 885:L P[885] 40mm/sec CNT1 ;
 886:L P[886] 40mm/sec CNT1 ;
 887:L P[887] 40mm/sec CNT1 ;
 888:L P[888] 40mm/sec CNT1 ;
 889:L P[889] 40mm/sec CNT1 ;
 890:L P[890] 40mm/sec CNT1 ;
 891:L P[891] 40mm/sec CNT1 ;
 892:L P[892] 40mm/sec CNT1 ;
 893:L P[893] 40mm/sec CNT1 ;
 894:L P[894] 40mm/sec CNT1 ;
 895:L P[895] 40mm/sec CNT1 ;
 896:L P[896] 40mm/sec CNT1 ;
 897:L P[897] 40mm/sec CNT1 ;
 898:L P[898] 40mm/sec CNT1 ;
 899:L P[899] 40mm/sec CNT1 ;
 900:L P[900] 40mm/sec CNT1 ;
 901:L P[901] 40mm/sec CNT1 ;
 902:L P[902] 40mm/sec CNT1 ;
 903:L P[903] 40mm/sec CNT1 ;
 904:L P[904] 40mm/sec CNT1 ;
 905:L P[905] 40mm/sec CNT1 ;
 906:L P[906] 40mm/sec CNT1 ;
 907:L P[907] 40mm/sec CNT1 ;
 908:L P[908] 40mm/sec CNT1 ;
 909:L P[909] 40mm/sec CNT1 ;
 910:L P[910] 40mm/sec CNT1 ;
 911:L P[911] 40mm/sec CNT1 ;
 912:L P[912] 40mm/sec CNT1 ;
 913:L P[913] 40mm/sec CNT1 ;
 914:L P[914] 40mm/sec CNT1 ;
 915:L P[915] 40mm/sec CNT1 ;
 916:L P[916] 40mm/sec CNT1 ;
 917:L P[917] 40mm/sec CNT1 ;
 918:L P[918] 40mm/sec CNT1 ;
 919:L P[919] 40mm/sec CNT1 ;
 920:L P[920] 40mm/sec CNT1 ;
 921:L P[921] 40mm/sec CNT1 ;
 922:L P[922] 40mm/sec CNT1 ;
 923:L P[923] 40mm/sec CNT1 ;
 924:L P[924] 40mm/sec CNT1 ;
 925:L P[925] 40mm/sec CNT1 ;
 926:L P[926] 40mm/sec CNT1 ;
 927:L P[927] 40mm/sec CNT1 ;
 928:L P[928] 40mm/sec CNT1 ;
 929:L P[929] 40mm/sec CNT1 ;
 930:L P[930] 40mm/sec CNT1 ;
 931:L P[931] 40mm/sec CNT1 ;
 932:L P[932] 40mm/sec CNT1 ;
 933:L P[933] 40mm/sec CNT1 ;
 934:L P[934] 40mm/sec CNT1 ;
 935:L P[935] 40mm/sec CNT1 ;
 936:L P[936] 40mm/sec CNT1 ;
 937:L P[937] 40mm/sec CNT1 ;
 938:L P[938] 40mm/sec CNT1 ;
 939:L P[939] 40mm/sec CNT1 ;
 940:L P[940] 40mm/sec CNT1 ;
 941:L P[941] 40mm/sec CNT1 ;
 942:L P[942] 40mm/sec CNT1 ;
 943:L P[943] 40mm/sec CNT1 ;
 944:L P[944] 40mm/sec CNT1 ;
 945:L P[945] 40mm/sec CNT1 ;
 946:L P[946] 40mm/sec CNT1 ;
 947:L P[947] 40mm/sec CNT1 ;
 948:L P[948] 40mm/sec CNT1 ;
 949:L P[949] 40mm/sec CNT1 ;
 950:L P[950] 40mm/sec CNT1 ;
 951:L P[951] 40mm/sec CNT1 ;
 952:L P[952] 40mm/sec CNT1 ;
 953:L P[953] 40mm/sec CNT1 ;
 954:L P[954] 40mm/sec CNT1 ;
 955:L P[955] 40mm/sec CNT1 ;
 956:L P[956] 40mm/sec CNT1 ;
 957:L P[957] 40mm/sec CNT1 ;
 958:L P[958] 40mm/sec CNT1 ;
 959:L P[959] 40mm/sec CNT1 ;
 960:L P[960] 40mm/sec CNT1 ;
 961:L P[961] 40mm/sec CNT1 ;
 962:L P[962] 40mm/sec CNT1 ;
 963:L P[963] 40mm/sec CNT1 ;
 964:L P[964] 40mm/sec CNT1 ;
 965:L P[965] 40mm/sec CNT1 ;
 966:L P[966] 40mm/sec CNT1 ;
 967:L P[967] 40mm/sec CNT1 ;
 968:L P[968] 40mm/sec CNT1 ;
 969:L P[969] 40mm/sec CNT1 ;
 970:L P[970] 40mm/sec CNT1 ;
 971:L P[971] 40mm/sec CNT1 ;
 972:L P[972] 40mm/sec CNT1 ;
 973:L P[973] 40mm/sec CNT1 ;
 974:L P[974] 40mm/sec CNT1 ;
 975:L P[975] 40mm/sec CNT1 ;
 976:L P[976] 40mm/sec CNT1 ;
 977:L P[977] 40mm/sec CNT1 ;
 978:L P[978] 40mm/sec CNT1 ;
 979:L P[979] 40mm/sec CNT1 ;
 980:L P[980] 40mm/sec CNT1 ;
 981:L P[981] 40mm/sec CNT1 ;
 982:L P[982] 40mm/sec CNT1 ;
 983:L P[983] 40mm/sec CNT1 ;
 984:L P[984] 40mm/sec CNT1 ;
 985:L P[985] 40mm/sec CNT1 ;
 986:L P[986] 40mm/sec CNT1 ;
 987:L P[987] 40mm/sec CNT1 ;
 988:L P[988] 40mm/sec CNT1 ;
 989:L P[989] 40mm/sec CNT1 ;
 990:L P[990] 40mm/sec CNT1 ;
 991:L P[991] 40mm/sec CNT1 ;
 992:L P[992] 40mm/sec CNT1 ;
 993:L P[993] 40mm/sec CNT1 ;
 994:L P[994] 40mm/sec CNT1 ;
 995:L P[995] 40mm/sec CNT1 ;
 996:L P[996] 40mm/sec CNT1 ;
 997:L P[997] 40mm/sec CNT1 ;
 998:L P[998] 40mm/sec CNT1 ;
 999:L P[999] 40mm/sec CNT1 ;
1000:L P[1000] 40mm/sec CNT1 ;
1001:L P[1001] 40mm/sec CNT1 ;
1002:L P[1002] 40mm/sec CNT1 ;
1003:L P[1003] 40mm/sec CNT1 ;
1004:L P[1004] 40mm/sec CNT1 ;
1005:L P[1005] 40mm/sec CNT1 ;
1006:L P[1006] 40mm/sec CNT1 ;
1007:L P[1007] 40mm/sec CNT1 ;
1008:L P[1008] 40mm/sec CNT1 ;
1009:L P[1009] 40mm/sec CNT1 ;
1010:L P[1010] 40mm/sec CNT1 ;
1011:L P[1011] 40mm/sec CNT1 ;
1012:L P[1012] 40mm/sec CNT1 ;
1013:L P[1013] 40mm/sec CNT1 ;
1014:L P[1014] 40mm/sec CNT1 ;
1015:L P[1015] 40mm/sec CNT1 ;
1016:L P[1016] 40mm/sec CNT1 ;
1017:L P[1017] 40mm/sec CNT1 ;
1018:L P[1018] 40mm/sec CNT1 ;
1019:L P[1019] 40mm/sec CNT1 ;
1020:L P[1020] 40mm/sec CNT1 ;
1021:L P[1021] 40mm/sec CNT1 ;
1022:L P[1022] 40mm/sec CNT1 ;
1023:L P[1023] 40mm/sec CNT1 ;
1024:L P[1024] 40mm/sec CNT1 ;
1025:L P[1025] 40mm/sec CNT1 ;
1026:L P[1026] 40mm/sec CNT1 ;
1027:L P[1027] 40mm/sec CNT1 ;
1028:L P[1028] 40mm/sec CNT1 ;
1029:L P[1029] 40mm/sec CNT1 ;
1030:L P[1030] 40mm/sec CNT1 ;
1031:L P[1031] 40mm/sec CNT1 ;
1032:L P[1032] 40mm/sec CNT1 ;
1033:L P[1033] 40mm/sec CNT1 ;
1034:L P[1034] 40mm/sec CNT1 ;
1035:L P[1035] 40mm/sec CNT1 ;
1036:L P[1036] 40mm/sec CNT1 ;
1037:L P[1037] 40mm/sec CNT1 ;
1038:L P[1038] 40mm/sec CNT1 ;
1039:L P[1039] 40mm/sec CNT1 ;
1040:L P[1040] 40mm/sec CNT1 ;
1041:L P[1041] 40mm/sec CNT1 ;
1042:L P[1042] 40mm/sec CNT1 ;
1043:L P[1043] 40mm/sec CNT1 ;
1044:L P[1044] 40mm/sec CNT1 ;
1045:L P[1045] 40mm/sec CNT1 ;
1046:L P[1046] 40mm/sec CNT1 ;
1047:L P[1047] 40mm/sec CNT1 ;
1048:L P[1048] 40mm/sec CNT1 ;
1049:L P[1049] 40mm/sec CNT1 ;
1050:L P[1050] 40mm/sec CNT1 ;
1051:L P[1051] 40mm/sec CNT1 ;
1052:L P[1052] 40mm/sec CNT1 ;
1053:L P[1053] 40mm/sec CNT1 ;
1054:L P[1054] 40mm/sec CNT1 ;
1055:L P[1055] 40mm/sec CNT1 ;
1056:L P[1056] 40mm/sec CNT1 ;
1057:L P[1057] 40mm/sec CNT1 ;
1058:L P[1058] 40mm/sec CNT1 ;
1059:L P[1059] 40mm/sec CNT1 ;
1060:L P[1060] 40mm/sec CNT1 ;
1061:L P[1061] 40mm/sec CNT1 ;
1062:L P[1062] 40mm/sec CNT1 ;
1063:L P[1063] 40mm/sec CNT1 ;
1064:L P[1064] 40mm/sec CNT1 ;
1065:L P[1065] 40mm/sec CNT1 ;
1066:L P[1066] 40mm/sec CNT1 ;
1067:L P[1067] 40mm/sec CNT1 ;
1068:L P[1068] 40mm/sec CNT1 ;
1069:L P[1069] 40mm/sec CNT1 ;
1070:L P[1070] 40mm/sec CNT1 ;
1071:L P[1071] 40mm/sec CNT1 ;
1072:L P[1072] 40mm/sec CNT1 ;
1073:L P[1073] 40mm/sec CNT1 ;
1074:L P[1074] 40mm/sec CNT1 ;
1075:L P[1075] 40mm/sec CNT1 ;
1076:L P[1076] 40mm/sec CNT1 ;
1077:L P[1077] 40mm/sec CNT1 ;
1078:L P[1078] 40mm/sec CNT1 ;
1079:L P[1079] 40mm/sec CNT1 ;
1080:L P[1080] 40mm/sec CNT1 ;
1081:L P[1081] 40mm/sec CNT1 ;
1082:L P[1082] 40mm/sec CNT1 ;
1083:L P[1083] 40mm/sec CNT1 ;
1084:L P[1084] 40mm/sec CNT1 ;
1085:L P[1085] 40mm/sec CNT1 ;
1086:L P[1086] 40mm/sec CNT1 ;
1087:L P[1087] 40mm/sec CNT1 ;
1088:L P[1088] 40mm/sec CNT1 ;
1089:L P[1089] 40mm/sec CNT1 ;
1090:L P[1090] 40mm/sec CNT1 ;
1091:L P[1091] 40mm/sec CNT1 ;
1092:L P[1092] 40mm/sec CNT1 ;
1093:L P[1093] 40mm/sec CNT1 ;
1094:L P[1094] 40mm/sec CNT1 ;
1095:L P[1095] 40mm/sec CNT1 ;
1096:L P[1096] 40mm/sec CNT1 ;
1097:L P[1097] 40mm/sec CNT1 ;
1098:L P[1098] 40mm/sec CNT1 ;
1099:L P[1099] 40mm/sec CNT1 ;
1100:L P[1100] 40mm/sec CNT1 ;
1101:L P[1101] 40mm/sec CNT1 ;
1102:L P[1102] 40mm/sec CNT1 ;
1103:L P[1103] 40mm/sec CNT1 ;
1104:L P[1104] 40mm/sec CNT1 ;
1105:L P[1105] 40mm/sec CNT1 ;
1106:L P[1106] 40mm/sec CNT1 ;
1107:L P[1107] 40mm/sec CNT1 ;
1108:L P[1108] 40mm/sec CNT1 ;
1109:L P[1109] 40mm/sec CNT1 ;
1110:L P[1110] 40mm/sec CNT1 ;
1111:L P[1111] 40mm/sec CNT1 ;
1112:L P[1112] 40mm/sec CNT1 ;
1113:L P[1113] 40mm/sec CNT1 ;
1114:L P[1114] 40mm/sec CNT1 ;
1115:L P[1115] 40mm/sec CNT1 ;
1116:L P[1116] 40mm/sec CNT1 ;
1117:L P[1117] 40mm/sec CNT1 ;
1118:L P[1118] 40mm/sec CNT1 ;
1119:L P[1119] 40mm/sec CNT1 ;
1120:L P[1120] 40mm/sec CNT1 ;
1121:L P[1121] 40mm/sec CNT1 ;
1122:L P[1122] 40mm/sec CNT1 ;
1123:L P[1123] 40mm/sec CNT1 ;
1124:L P[1124] 40mm/sec CNT1 ;
1125:L P[1125] 40mm/sec CNT1 ;
1126:L P[1126] 40mm/sec CNT1 ;
1127:L P[1127] 40mm/sec CNT1 ;
1128:L P[1128] 40mm/sec CNT1 ;
1129:L P[1129] 40mm/sec CNT1 ;
1130:L P[1130] 40mm/sec CNT1 ;
1131:L P[1131] 40mm/sec CNT1 ;
1132:L P[1132] 40mm/sec CNT1 ;
1133:L P[1133] 40mm/sec CNT1 ;
1134:L P[1134] 40mm/sec CNT1 ;
1135:L P[1135] 40mm/sec CNT1 ;
1136:L P[1136] 40mm/sec CNT1 ;
1137:L P[1137] 40mm/sec CNT1 ;
1138:L P[1138] 40mm/sec CNT1 ;
1139:L P[1139] 40mm/sec CNT1 ;
1140:L P[1140] 40mm/sec CNT1 ;
1141:L P[1141] 40mm/sec CNT1 ;
1142:L P[1142] 40mm/sec CNT1 ;
1143:L P[1143] 40mm/sec CNT1 ;
1144:L P[1144] 40mm/sec CNT1 ;
1145:L P[1145] 40mm/sec CNT1 ;
1146:L P[1146] 40mm/sec CNT1 ;
1147:L P[1147] 40mm/sec CNT1 ;
1148:L P[1148] 40mm/sec CNT1 ;
1149:L P[1149] 40mm/sec CNT1 ;
1150:L P[1150] 40mm/sec CNT1 ;
1151:L P[1151] 40mm/sec CNT1 ;
1152:L P[1152] 40mm/sec CNT1 ;
1153:L P[1153] 40mm/sec CNT1 ;
1154:L P[1154] 40mm/sec CNT1 ;
1155:L P[1155] 40mm/sec CNT1 ;
1156:L P[1156] 40mm/sec CNT1 ;
1157:L P[1157] 40mm/sec CNT1 ;
1158:L P[1158] 40mm/sec CNT1 ;
1159:L P[1159] 40mm/sec CNT1 ;
1160:L P[1160] 40mm/sec CNT1 ;
1161:L P[1161] 40mm/sec CNT1 ;
1162:L P[1162] 40mm/sec CNT1 ;
1163:L P[1163] 40mm/sec CNT1 ;
1164:L P[1164] 40mm/sec CNT1 ;
1165:L P[1165] 40mm/sec CNT1 ;
1166:L P[1166] 40mm/sec CNT1 ;
1167:L P[1167] 40mm/sec CNT1 ;
1168:L P[1168] 40mm/sec CNT1 ;
1169:L P[1169] 40mm/sec CNT1 ;
1170:L P[1170] 40mm/sec CNT1 ;
1171:L P[1171] 40mm/sec CNT1 ;
1172:L P[1172] 40mm/sec CNT1 ;
1173:L P[1173] 40mm/sec CNT1 ;
1174:L P[1174] 40mm/sec CNT1 ;
1175:L P[1175] 40mm/sec CNT1 ;
1176:L P[1176] 40mm/sec CNT1 ;
1177:L P[1177] 40mm/sec CNT1 ;
1178:L P[1178] 40mm/sec CNT1 ;
1179:L P[1179] 40mm/sec CNT1 ;
1180:L P[1180] 40mm/sec CNT1 ;
1181:L P[1181] 40mm/sec CNT1 ;
1182:L P[1182] 40mm/sec CNT1 ;
1183:L P[1183] 40mm/sec CNT1 ;
1184:L P[1184] 40mm/sec CNT1 ;
1185:L P[1185] 40mm/sec CNT1 ;
1186:L P[1186] 40mm/sec CNT1 ;
1187:L P[1187] 40mm/sec CNT1 ;
1188:L P[1188] 40mm/sec CNT1 ;
1189:L P[1189] 40mm/sec CNT1 ;
1190:L P[1190] 40mm/sec CNT1 ;
1191:L P[1191] 40mm/sec CNT1 ;
1192:L P[1192] 40mm/sec CNT1 ;
1193:L P[1193] 40mm/sec CNT1 ;
1194:L P[1194] 40mm/sec CNT1 ;
1195:L P[1195] 40mm/sec CNT1 ;
1196:L P[1196] 40mm/sec CNT1 ;
1197:L P[1197] 40mm/sec CNT1 ;
1198:L P[1198] 40mm/sec CNT1 ;
1199:L P[1199] 40mm/sec CNT1 ;
1200:L P[1200] 40mm/sec CNT1 ;
1201:L P[1201] 40mm/sec CNT1 ;
1202:L P[1202] 40mm/sec CNT1 ;
1203:L P[1203] 40mm/sec CNT1 ;
1204:L P[1204] 40mm/sec CNT1 ;
1205:L P[1205] 40mm/sec CNT1 ;
1206:L P[1206] 40mm/sec CNT1 ;
1207:L P[1207] 40mm/sec CNT1 ;
1208:L P[1208] 40mm/sec CNT1 ;
1209:L P[1209] 40mm/sec CNT1 ;
1210:L P[1210] 40mm/sec CNT1 ;
1211:L P[1211] 40mm/sec CNT1 ;
1212:L P[1212] 40mm/sec CNT1 ;
1213:L P[1213] 40mm/sec CNT1 ;
1214:L P[1214] 40mm/sec CNT1 ;
1215:L P[1215] 40mm/sec CNT1 ;
1216:L P[1216] 40mm/sec CNT1 ;
1217:L P[1217] 40mm/sec CNT1 ;
1218:L P[1218] 40mm/sec CNT1 ;
1219:L P[1219] 40mm/sec CNT1 ;
1220:L P[1220] 40mm/sec CNT1 ;
1221:L P[1221] 40mm/sec FINE ;
/POS
P[1 : "approach"]{
   GP1:
	UF : 0, UT : 1,
	J1=   -9.011 deg,	J2=  -49.636 deg,	J3=   50.884 deg,
	J4=    2.939 deg,	J5=   15.717 deg,	J6=   97.959 deg
};
P[2]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  573.505  mm,	Y =  -78.620  mm,	Z =  367.581  mm,
	W = -166.061 deg,	P =   -4.895 deg,	R =   88.787 deg
};
P[3]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  571.911  mm,	Y =  -78.034  mm,	Z =  361.134  mm,
	W = -166.061 deg,	P =   -4.895 deg,	R =   88.787 deg
};
P[4]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.361  mm,	Y =  -77.097  mm,	Z =  350.819  mm,
	W = -166.061 deg,	P =   -4.895 deg,	R =   88.787 deg
};
P[5]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.382  mm,	Y =  -74.126  mm,	Z =  351.077  mm,
	W = -166.480 deg,	P =   -4.663 deg,	R =   88.880 deg
};
P[6]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.387  mm,	Y =  -71.152  mm,	Z =  351.326  mm,
	W = -166.915 deg,	P =   -4.452 deg,	R =   88.966 deg
};
P[7]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.397  mm,	Y =  -68.177  mm,	Z =  351.562  mm,
	W = -167.339 deg,	P =   -4.248 deg,	R =   89.047 deg
};
P[8]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.414  mm,	Y =  -65.199  mm,	Z =  351.786  mm,
	W = -167.743 deg,	P =   -4.084 deg,	R =   89.114 deg
};
P[9]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.417  mm,	Y =  -62.219  mm,	Z =  352.003  mm,
	W = -168.131 deg,	P =   -3.920 deg,	R =   89.177 deg
};
P[10]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.438  mm,	Y =  -59.236  mm,	Z =  352.208  mm,
	W = -168.498 deg,	P =   -3.788 deg,	R =   89.230 deg
};
P[11]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.444  mm,	Y =  -56.253  mm,	Z =  352.408  mm,
	W = -168.819 deg,	P =   -3.661 deg,	R =   89.277 deg
};
P[12]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.455  mm,	Y =  -53.269  mm,	Z =  352.601  mm,
	W = -169.114 deg,	P =   -3.530 deg,	R =   89.322 deg
};
P[13]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.467  mm,	Y =  -50.280  mm,	Z =  352.789  mm,
	W = -169.363 deg,	P =   -3.457 deg,	R =   89.351 deg
};
P[14]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.471  mm,	Y =  -47.293  mm,	Z =  352.972  mm,
	W = -169.562 deg,	P =   -3.365 deg,	R =   89.381 deg
};
P[15]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.482  mm,	Y =  -44.303  mm,	Z =  353.149  mm,
	W = -169.729 deg,	P =   -3.294 deg,	R =   89.403 deg
};
P[16]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.485  mm,	Y =  -41.314  mm,	Z =  353.324  mm,
	W = -169.814 deg,	P =   -3.217 deg,	R =   89.422 deg
};
P[17]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.489  mm,	Y =  -38.326  mm,	Z =  353.495  mm,
	W = -169.863 deg,	P =   -3.120 deg,	R =   89.442 deg
};
P[18]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.489  mm,	Y =  -35.333  mm,	Z =  353.662  mm,
	W = -169.859 deg,	P =   -3.078 deg,	R =   89.450 deg
};
P[19]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.491  mm,	Y =  -32.343  mm,	Z =  353.826  mm,
	W = -169.793 deg,	P =   -3.001 deg,	R =   89.460 deg
};
P[20]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.487  mm,	Y =  -29.353  mm,	Z =  353.987  mm,
	W = -169.692 deg,	P =   -2.927 deg,	R =   89.468 deg
};
P[21]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.484  mm,	Y =  -26.363  mm,	Z =  354.142  mm,
	W = -169.510 deg,	P =   -2.835 deg,	R =   89.475 deg
};
P[22]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.481  mm,	Y =  -23.373  mm,	Z =  354.294  mm,
	W = -169.323 deg,	P =   -2.743 deg,	R =   89.483 deg
};
P[23]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.470  mm,	Y =  -20.385  mm,	Z =  354.441  mm,
	W = -169.040 deg,	P =   -2.625 deg,	R =   89.492 deg
};
P[24]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.469  mm,	Y =  -17.397  mm,	Z =  354.580  mm,
	W = -168.736 deg,	P =   -2.500 deg,	R =   89.502 deg
};
P[25]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.452  mm,	Y =  -14.410  mm,	Z =  354.715  mm,
	W = -168.409 deg,	P =   -2.353 deg,	R =   89.517 deg
};
P[26]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.448  mm,	Y =  -11.424  mm,	Z =  354.839  mm,
	W = -168.033 deg,	P =   -2.190 deg,	R =   89.536 deg
};
P[27]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.438  mm,	Y =   -8.438  mm,	Z =  354.956  mm,
	W = -167.657 deg,	P =   -2.009 deg,	R =   89.561 deg
};
P[28]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.424  mm,	Y =   -5.455  mm,	Z =  355.063  mm,
	W = -167.238 deg,	P =   -1.803 deg,	R =   89.592 deg
};
P[29]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.423  mm,	Y =   -2.473  mm,	Z =  355.156  mm,
	W = -166.815 deg,	P =   -1.568 deg,	R =   89.633 deg
};
P[30]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.403  mm,	Y =    0.510  mm,	Z =  355.241  mm,
	W = -166.397 deg,	P =   -1.334 deg,	R =   89.677 deg
};
P[31]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.400  mm,	Y =    3.491  mm,	Z =  355.308  mm,
	W = -165.972 deg,	P =   -1.075 deg,	R =   89.731 deg
};
P[32]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.389  mm,	Y =    6.469  mm,	Z =  355.363  mm,
	W = -165.560 deg,	P =   -0.786 deg,	R =   89.798 deg
};
P[33]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.377  mm,	Y =    9.448  mm,	Z =  355.401  mm,
	W = -165.165 deg,	P =   -0.487 deg,	R =   89.871 deg
};
P[34]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.351  mm,	Y =   12.425  mm,	Z =  355.427  mm,
	W = -164.788 deg,	P =   -0.178 deg,	R =   89.951 deg
};
P[35]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.355  mm,	Y =   15.400  mm,	Z =  355.426  mm,
	W = -164.439 deg,	P =    0.168 deg,	R =   90.047 deg
};
P[36]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.344  mm,	Y =   18.375  mm,	Z =  355.410  mm,
	W = -164.123 deg,	P =    0.507 deg,	R =   90.144 deg
};
P[37]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.339  mm,	Y =   21.348  mm,	Z =  355.373  mm,
	W = -163.834 deg,	P =    0.880 deg,	R =   90.255 deg
};
P[38]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.338  mm,	Y =   24.321  mm,	Z =  355.314  mm,
	W = -163.603 deg,	P =    1.245 deg,	R =   90.366 deg
};
P[39]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.329  mm,	Y =   27.293  mm,	Z =  355.235  mm,
	W = -163.406 deg,	P =    1.610 deg,	R =   90.480 deg
};
P[40]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.331  mm,	Y =   30.261  mm,	Z =  355.132  mm,
	W = -163.255 deg,	P =    2.017 deg,	R =   90.607 deg
};
P[41]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.326  mm,	Y =   33.230  mm,	Z =  355.009  mm,
	W = -163.156 deg,	P =    2.402 deg,	R =   90.727 deg
};
P[42]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.325  mm,	Y =   36.197  mm,	Z =  354.862  mm,
	W = -163.095 deg,	P =    2.810 deg,	R =   90.854 deg
};
P[43]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.324  mm,	Y =   39.163  mm,	Z =  354.692  mm,
	W = -163.108 deg,	P =    3.202 deg,	R =   90.972 deg
};
P[44]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.325  mm,	Y =   42.127  mm,	Z =  354.499  mm,
	W = -163.133 deg,	P =    3.611 deg,	R =   91.094 deg
};
P[45]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.323  mm,	Y =   45.092  mm,	Z =  354.285  mm,
	W = -163.258 deg,	P =    4.000 deg,	R =   91.202 deg
};
P[46]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.325  mm,	Y =   48.054  mm,	Z =  354.048  mm,
	W = -163.407 deg,	P =    4.391 deg,	R =   91.307 deg
};
P[47]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.329  mm,	Y =   51.015  mm,	Z =  353.789  mm,
	W = -163.596 deg,	P =    4.782 deg,	R =   91.406 deg
};
P[48]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.327  mm,	Y =   53.975  mm,	Z =  353.510  mm,
	W = -163.845 deg,	P =    5.159 deg,	R =   91.492 deg
};
P[49]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.340  mm,	Y =   56.934  mm,	Z =  353.207  mm,
	W = -164.105 deg,	P =    5.532 deg,	R =   91.573 deg
};
P[50]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.336  mm,	Y =   59.892  mm,	Z =  352.889  mm,
	W = -164.438 deg,	P =    5.887 deg,	R =   91.636 deg
};
P[51]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.347  mm,	Y =   62.851  mm,	Z =  352.549  mm,
	W = -164.785 deg,	P =    6.210 deg,	R =   91.685 deg
};
P[52]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.354  mm,	Y =   65.806  mm,	Z =  352.192  mm,
	W = -165.152 deg,	P =    6.560 deg,	R =   91.735 deg
};
P[53]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.357  mm,	Y =   68.761  mm,	Z =  351.819  mm,
	W = -165.549 deg,	P =    6.877 deg,	R =   91.767 deg
};
P[54]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.376  mm,	Y =   71.716  mm,	Z =  351.427  mm,
	W = -165.948 deg,	P =    7.165 deg,	R =   91.788 deg
};
P[55]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.376  mm,	Y =   74.671  mm,	Z =  351.026  mm,
	W = -166.370 deg,	P =    7.442 deg,	R =   91.799 deg
};
P[56]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.394  mm,	Y =   77.625  mm,	Z =  350.607  mm,
	W = -166.781 deg,	P =    7.694 deg,	R =   91.801 deg
};
P[57]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.403  mm,	Y =   80.579  mm,	Z =  350.178  mm,
	W = -167.196 deg,	P =    7.926 deg,	R =   91.795 deg
};
P[58]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.413  mm,	Y =   83.533  mm,	Z =  349.738  mm,
	W = -167.599 deg,	P =    8.147 deg,	R =   91.785 deg
};
P[59]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.431  mm,	Y =   86.487  mm,	Z =  349.287  mm,
	W = -167.979 deg,	P =    8.326 deg,	R =   91.766 deg
};
P[60]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.435  mm,	Y =   89.441  mm,	Z =  348.830  mm,
	W = -168.336 deg,	P =    8.503 deg,	R =   91.748 deg
};
P[61]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.453  mm,	Y =   92.396  mm,	Z =  348.362  mm,
	W = -168.673 deg,	P =    8.647 deg,	R =   91.725 deg
};
P[62]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.460  mm,	Y =   95.350  mm,	Z =  347.890  mm,
	W = -168.954 deg,	P =    8.782 deg,	R =   91.707 deg
};
P[63]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.470  mm,	Y =   98.302  mm,	Z =  347.412  mm,
	W = -169.209 deg,	P =    8.921 deg,	R =   91.693 deg
};
P[64]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.480  mm,	Y =  101.258  mm,	Z =  346.928  mm,
	W = -169.417 deg,	P =    8.998 deg,	R =   91.674 deg
};
P[65]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.485  mm,	Y =  104.212  mm,	Z =  346.441  mm,
	W = -169.573 deg,	P =    9.094 deg,	R =   91.666 deg
};
P[66]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.493  mm,	Y =  107.167  mm,	Z =  345.949  mm,
	W = -169.695 deg,	P =    9.167 deg,	R =   91.659 deg
};
P[67]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.495  mm,	Y =  110.120  mm,	Z =  345.454  mm,
	W = -169.736 deg,	P =    9.243 deg,	R =   91.666 deg
};
P[68]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.500  mm,	Y =  113.074  mm,	Z =  344.955  mm,
	W = -169.768 deg,	P =    9.306 deg,	R =   91.672 deg
};
P[69]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.497  mm,	Y =  116.027  mm,	Z =  344.454  mm,
	W = -169.691 deg,	P =    9.376 deg,	R =   91.697 deg
};
P[70]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.499  mm,	Y =  118.979  mm,	Z =  343.948  mm,
	W = -169.586 deg,	P =    9.444 deg,	R =   91.727 deg
};
P[71]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.492  mm,	Y =  121.930  mm,	Z =  343.440  mm,
	W = -169.439 deg,	P =    9.512 deg,	R =   91.765 deg
};
P[72]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.491  mm,	Y =  124.879  mm,	Z =  342.927  mm,
	W = -169.223 deg,	P =    9.589 deg,	R =   91.816 deg
};
P[73]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.485  mm,	Y =  127.827  mm,	Z =  342.410  mm,
	W = -168.993 deg,	P =    9.670 deg,	R =   91.871 deg
};
P[74]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.476  mm,	Y =  130.773  mm,	Z =  341.887  mm,
	W = -168.682 deg,	P =    9.766 deg,	R =   91.944 deg
};
P[75]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.473  mm,	Y =  133.715  mm,	Z =  341.358  mm,
	W = -168.350 deg,	P =    9.895 deg,	R =   92.029 deg
};
P[76]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.457  mm,	Y =  136.658  mm,	Z =  340.824  mm,
	W = -167.995 deg,	P =    9.991 deg,	R =   92.113 deg
};
P[77]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.090  mm,	Y =  139.329  mm,	Z =  340.621  mm,
	W = -167.845 deg,	P =    9.947 deg,	R =   92.131 deg
};
P[78]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.178  mm,	Y =  139.502  mm,	Z =  341.196  mm,
	W = -168.262 deg,	P =    9.613 deg,	R =   91.987 deg
};
P[79]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  562.265  mm,	Y =  139.509  mm,	Z =  341.781  mm,
	W = -168.698 deg,	P =    9.270 deg,	R =   91.844 deg
};
P[80]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  559.347  mm,	Y =  139.524  mm,	Z =  342.342  mm,
	W = -169.131 deg,	P =    8.928 deg,	R =   91.707 deg
};
P[81]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  556.425  mm,	Y =  139.535  mm,	Z =  342.883  mm,
	W = -169.562 deg,	P =    8.587 deg,	R =   91.576 deg
};
P[82]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  553.500  mm,	Y =  139.547  mm,	Z =  343.403  mm,
	W = -169.988 deg,	P =    8.248 deg,	R =   91.451 deg
};
P[83]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.571  mm,	Y =  139.562  mm,	Z =  343.902  mm,
	W = -170.416 deg,	P =    7.915 deg,	R =   91.332 deg
};
P[84]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.638  mm,	Y =  139.572  mm,	Z =  344.380  mm,
	W = -170.839 deg,	P =    7.582 deg,	R =   91.219 deg
};
P[85]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.701  mm,	Y =  139.589  mm,	Z =  344.836  mm,
	W = -171.259 deg,	P =    7.260 deg,	R =   91.113 deg
};
P[86]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  541.762  mm,	Y =  139.601  mm,	Z =  345.272  mm,
	W = -171.678 deg,	P =    6.940 deg,	R =   91.013 deg
};
P[87]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  538.819  mm,	Y =  139.614  mm,	Z =  345.687  mm,
	W = -172.094 deg,	P =    6.630 deg,	R =   90.919 deg
};
P[88]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  535.874  mm,	Y =  139.629  mm,	Z =  346.081  mm,
	W = -172.507 deg,	P =    6.328 deg,	R =   90.831 deg
};
P[89]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  532.925  mm,	Y =  139.641  mm,	Z =  346.455  mm,
	W = -172.919 deg,	P =    6.029 deg,	R =   90.747 deg
};
P[90]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.974  mm,	Y =  139.657  mm,	Z =  346.807  mm,
	W = -173.327 deg,	P =    5.753 deg,	R =   90.672 deg
};
P[91]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.021  mm,	Y =  139.669  mm,	Z =  347.139  mm,
	W = -173.734 deg,	P =    5.477 deg,	R =   90.600 deg
};
P[92]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  524.065  mm,	Y =  139.682  mm,	Z =  347.450  mm,
	W = -174.139 deg,	P =    5.223 deg,	R =   90.535 deg
};
P[93]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  521.107  mm,	Y =  139.695  mm,	Z =  347.741  mm,
	W = -174.542 deg,	P =    4.974 deg,	R =   90.475 deg
};
P[94]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  518.147  mm,	Y =  139.706  mm,	Z =  348.012  mm,
	W = -174.943 deg,	P =    4.742 deg,	R =   90.419 deg
};
P[95]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  515.185  mm,	Y =  139.719  mm,	Z =  348.261  mm,
	W = -175.343 deg,	P =    4.525 deg,	R =   90.368 deg
};
P[96]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  512.222  mm,	Y =  139.729  mm,	Z =  348.491  mm,
	W = -175.742 deg,	P =    4.314 deg,	R =   90.321 deg
};
P[97]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.257  mm,	Y =  139.739  mm,	Z =  348.700  mm,
	W = -176.138 deg,	P =    4.135 deg,	R =   90.279 deg
};
P[98]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.290  mm,	Y =  139.749  mm,	Z =  348.889  mm,
	W = -176.534 deg,	P =    3.959 deg,	R =   90.240 deg
};
P[99]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  503.322  mm,	Y =  139.757  mm,	Z =  349.058  mm,
	W = -176.928 deg,	P =    3.809 deg,	R =   90.204 deg
};
P[100]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.353  mm,	Y =  139.765  mm,	Z =  349.206  mm,
	W = -177.322 deg,	P =    3.671 deg,	R =   90.172 deg
};
P[101]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  497.383  mm,	Y =  139.772  mm,	Z =  349.334  mm,
	W = -177.715 deg,	P =    3.541 deg,	R =   90.141 deg
};
P[102]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  494.412  mm,	Y =  139.777  mm,	Z =  349.442  mm,
	W = -178.106 deg,	P =    3.453 deg,	R =   90.114 deg
};
P[103]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  491.441  mm,	Y =  139.783  mm,	Z =  349.529  mm,
	W = -178.498 deg,	P =    3.363 deg,	R =   90.088 deg
};
P[104]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.469  mm,	Y =  139.786  mm,	Z =  349.597  mm,
	W = -178.888 deg,	P =    3.306 deg,	R =   90.064 deg
};
P[105]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.496  mm,	Y =  139.789  mm,	Z =  349.644  mm,
	W = -179.279 deg,	P =    3.258 deg,	R =   90.041 deg
};
P[106]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.523  mm,	Y =  139.790  mm,	Z =  349.671  mm,
	W = -179.654 deg,	P =    3.234 deg,	R =   90.020 deg
};
P[107]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.551  mm,	Y =  139.790  mm,	Z =  349.678  mm,
	W =  179.941 deg,	P =    3.229 deg,	R =   89.997 deg
};
P[108]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.578  mm,	Y =  139.790  mm,	Z =  349.665  mm,
	W =  179.550 deg,	P =    3.232 deg,	R =   89.975 deg
};
P[109]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.605  mm,	Y =  139.787  mm,	Z =  349.632  mm,
	W =  179.160 deg,	P =    3.274 deg,	R =   89.952 deg
};
P[110]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.633  mm,	Y =  139.784  mm,	Z =  349.579  mm,
	W =  178.769 deg,	P =    3.319 deg,	R =   89.929 deg
};
P[111]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.661  mm,	Y =  139.779  mm,	Z =  349.505  mm,
	W =  178.379 deg,	P =    3.393 deg,	R =   89.904 deg
};
P[112]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.690  mm,	Y =  139.774  mm,	Z =  349.411  mm,
	W =  177.987 deg,	P =    3.480 deg,	R =   89.878 deg
};
P[113]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.719  mm,	Y =  139.768  mm,	Z =  349.297  mm,
	W =  177.595 deg,	P =    3.576 deg,	R =   89.850 deg
};
P[114]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  458.750  mm,	Y =  139.760  mm,	Z =  349.163  mm,
	W =  177.202 deg,	P =    3.713 deg,	R =   89.819 deg
};
P[115]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  455.781  mm,	Y =  139.752  mm,	Z =  349.009  mm,
	W =  176.808 deg,	P =    3.849 deg,	R =   89.786 deg
};
P[116]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  452.813  mm,	Y =  139.742  mm,	Z =  348.834  mm,
	W =  176.414 deg,	P =    4.015 deg,	R =   89.749 deg
};
P[117]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  449.847  mm,	Y =  139.732  mm,	Z =  348.639  mm,
	W =  176.018 deg,	P =    4.189 deg,	R =   89.709 deg
};
P[118]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  446.882  mm,	Y =  139.721  mm,	Z =  348.424  mm,
	W =  175.634 deg,	P =    4.384 deg,	R =   89.666 deg
};
P[119]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.920  mm,	Y =  139.709  mm,	Z =  348.189  mm,
	W =  175.222 deg,	P =    4.591 deg,	R =   89.617 deg
};
P[120]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.958  mm,	Y =  139.698  mm,	Z =  347.933  mm,
	W =  174.821 deg,	P =    4.807 deg,	R =   89.565 deg
};
P[121]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  437.999  mm,	Y =  139.683  mm,	Z =  347.656  mm,
	W =  174.421 deg,	P =    5.052 deg,	R =   89.507 deg
};
P[122]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  435.041  mm,	Y =  139.671  mm,	Z =  347.359  mm,
	W =  174.016 deg,	P =    5.298 deg,	R =   89.445 deg
};
P[123]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  432.086  mm,	Y =  139.656  mm,	Z =  347.042  mm,
	W =  173.612 deg,	P =    5.565 deg,	R =   89.378 deg
};
P[124]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  429.134  mm,	Y =  139.642  mm,	Z =  346.704  mm,
	W =  173.204 deg,	P =    5.839 deg,	R =   89.305 deg
};
P[125]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  426.183  mm,	Y =  139.629  mm,	Z =  346.345  mm,
	W =  172.794 deg,	P =    6.118 deg,	R =   89.228 deg
};
P[126]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.236  mm,	Y =  139.612  mm,	Z =  345.966  mm,
	W =  172.383 deg,	P =    6.422 deg,	R =   89.143 deg
};
P[127]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.291  mm,	Y =  139.599  mm,	Z =  345.565  mm,
	W =  171.968 deg,	P =    6.723 deg,	R =   89.054 deg
};
P[128]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  417.349  mm,	Y =  139.583  mm,	Z =  345.144  mm,
	W =  171.553 deg,	P =    7.041 deg,	R =   88.957 deg
};
P[129]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  414.411  mm,	Y =  139.568  mm,	Z =  344.703  mm,
	W =  171.134 deg,	P =    7.359 deg,	R =   88.855 deg
};
P[130]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  411.475  mm,	Y =  139.555  mm,	Z =  344.240  mm,
	W =  170.713 deg,	P =    7.687 deg,	R =   88.747 deg
};
P[131]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  408.543  mm,	Y =  139.539  mm,	Z =  343.756  mm,
	W =  170.289 deg,	P =    8.019 deg,	R =   88.633 deg
};
P[132]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.615  mm,	Y =  139.527  mm,	Z =  343.251  mm,
	W =  169.862 deg,	P =    8.352 deg,	R =   88.512 deg
};
P[133]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.691  mm,	Y =  139.513  mm,	Z =  342.725  mm,
	W =  169.434 deg,	P =    8.694 deg,	R =   88.385 deg
};
P[134]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  399.770  mm,	Y =  139.499  mm,	Z =  342.178  mm,
	W =  169.002 deg,	P =    9.034 deg,	R =   88.252 deg
};
P[135]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  396.854  mm,	Y =  139.488  mm,	Z =  341.609  mm,
	W =  168.569 deg,	P =    9.377 deg,	R =   88.113 deg
};
P[136]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  393.942  mm,	Y =  139.473  mm,	Z =  341.020  mm,
	W =  168.133 deg,	P =    9.719 deg,	R =   87.968 deg
};
P[137]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  391.093  mm,	Y =  138.702  mm,	Z =  340.563  mm,
	W =  167.827 deg,	P =   10.017 deg,	R =   87.851 deg
};
P[138]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.558  mm,	Y =  135.784  mm,	Z =  340.987  mm,
	W =  168.102 deg,	P =    9.957 deg,	R =   87.914 deg
};
P[139]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.549  mm,	Y =  132.842  mm,	Z =  341.520  mm,
	W =  168.453 deg,	P =    9.837 deg,	R =   88.001 deg
};
P[140]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.538  mm,	Y =  129.897  mm,	Z =  342.046  mm,
	W =  168.784 deg,	P =    9.743 deg,	R =   88.078 deg
};
P[141]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.530  mm,	Y =  126.950  mm,	Z =  342.567  mm,
	W =  169.052 deg,	P =    9.649 deg,	R =   88.143 deg
};
P[142]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.522  mm,	Y =  124.003  mm,	Z =  343.082  mm,
	W =  169.294 deg,	P =    9.543 deg,	R =   88.205 deg
};
P[143]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.515  mm,	Y =  121.051  mm,	Z =  343.594  mm,
	W =  169.484 deg,	P =    9.498 deg,	R =   88.246 deg
};
P[144]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.510  mm,	Y =  118.100  mm,	Z =  344.101  mm,
	W =  169.620 deg,	P =    9.423 deg,	R =   88.282 deg
};
P[145]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.505  mm,	Y =  115.148  mm,	Z =  344.604  mm,
	W =  169.724 deg,	P =    9.365 deg,	R =   88.310 deg
};
P[146]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.504  mm,	Y =  112.195  mm,	Z =  345.105  mm,
	W =  169.744 deg,	P =    9.293 deg,	R =   88.326 deg
};
P[147]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.501  mm,	Y =  109.241  mm,	Z =  345.601  mm,
	W =  169.757 deg,	P =    9.232 deg,	R =   88.339 deg
};
P[148]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.505  mm,	Y =  106.287  mm,	Z =  346.095  mm,
	W =  169.657 deg,	P =    9.151 deg,	R =   88.337 deg
};
P[149]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.507  mm,	Y =  103.333  mm,	Z =  346.585  mm,
	W =  169.532 deg,	P =    9.068 deg,	R =   88.332 deg
};
P[150]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.512  mm,	Y =  100.378  mm,	Z =  347.071  mm,
	W =  169.368 deg,	P =    8.977 deg,	R =   88.322 deg
};
P[151]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.518  mm,	Y =   97.424  mm,	Z =  347.552  mm,
	W =  169.135 deg,	P =    8.868 deg,	R =   88.305 deg
};
P[152]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.524  mm,	Y =   94.469  mm,	Z =  348.028  mm,
	W =  168.892 deg,	P =    8.751 deg,	R =   88.289 deg
};
P[153]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.534  mm,	Y =   91.516  mm,	Z =  348.499  mm,
	W =  168.570 deg,	P =    8.607 deg,	R =   88.267 deg
};
P[154]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.542  mm,	Y =   88.563  mm,	Z =  348.962  mm,
	W =  168.233 deg,	P =    8.426 deg,	R =   88.251 deg
};
P[155]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.553  mm,	Y =   85.607  mm,	Z =  349.418  mm,
	W =  167.872 deg,	P =    8.273 deg,	R =   88.229 deg
};
P[156]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.561  mm,	Y =   82.653  mm,	Z =  349.864  mm,
	W =  167.478 deg,	P =    8.079 deg,	R =   88.212 deg
};
P[157]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.572  mm,	Y =   79.699  mm,	Z =  350.301  mm,
	W =  167.083 deg,	P =    7.858 deg,	R =   88.204 deg
};
P[158]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.582  mm,	Y =   76.745  mm,	Z =  350.726  mm,
	W =  166.662 deg,	P =    7.618 deg,	R =   88.200 deg
};
P[159]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.593  mm,	Y =   73.791  mm,	Z =  351.139  mm,
	W =  166.243 deg,	P =    7.350 deg,	R =   88.206 deg
};
P[160]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.602  mm,	Y =   70.836  mm,	Z =  351.539  mm,
	W =  165.834 deg,	P =    7.075 deg,	R =   88.219 deg
};
P[161]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.611  mm,	Y =   67.880  mm,	Z =  351.924  mm,
	W =  165.427 deg,	P =    6.784 deg,	R =   88.241 deg
};
P[162]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.620  mm,	Y =   64.925  mm,	Z =  352.293  mm,
	W =  165.041 deg,	P =    6.455 deg,	R =   88.279 deg
};
P[163]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.628  mm,	Y =   61.969  mm,	Z =  352.645  mm,
	W =  164.678 deg,	P =    6.127 deg,	R =   88.325 deg
};
P[164]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.638  mm,	Y =   59.012  mm,	Z =  352.979  mm,
	W =  164.331 deg,	P =    5.771 deg,	R =   88.385 deg
};
P[165]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.643  mm,	Y =   56.053  mm,	Z =  353.294  mm,
	W =  164.036 deg,	P =    5.413 deg,	R =   88.454 deg
};
P[166]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.651  mm,	Y =   53.092  mm,	Z =  353.589  mm,
	W =  163.764 deg,	P =    5.063 deg,	R =   88.528 deg
};
P[167]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.656  mm,	Y =   50.134  mm,	Z =  353.864  mm,
	W =  163.537 deg,	P =    4.655 deg,	R =   88.626 deg
};
P[168]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.662  mm,	Y =   47.172  mm,	Z =  354.117  mm,
	W =  163.359 deg,	P =    4.275 deg,	R =   88.724 deg
};
P[169]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.668  mm,	Y =   44.210  mm,	Z =  354.349  mm,
	W =  163.209 deg,	P =    3.868 deg,	R =   88.834 deg
};
P[170]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.670  mm,	Y =   41.245  mm,	Z =  354.558  mm,
	W =  163.138 deg,	P =    3.479 deg,	R =   88.946 deg
};
P[171]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.677  mm,	Y =   38.279  mm,	Z =  354.745  mm,
	W =  163.100 deg,	P =    3.105 deg,	R =   89.057 deg
};
P[172]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.678  mm,	Y =   35.314  mm,	Z =  354.909  mm,
	W =  163.112 deg,	P =    2.678 deg,	R =   89.187 deg
};
P[173]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.682  mm,	Y =   32.346  mm,	Z =  355.051  mm,
	W =  163.182 deg,	P =    2.288 deg,	R =   89.309 deg
};
P[174]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.683  mm,	Y =   29.378  mm,	Z =  355.169  mm,
	W =  163.283 deg,	P =    1.887 deg,	R =   89.433 deg
};
P[175]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.683  mm,	Y =   26.407  mm,	Z =  355.265  mm,
	W =  163.461 deg,	P =    1.507 deg,	R =   89.553 deg
};
P[176]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.683  mm,	Y =   23.435  mm,	Z =  355.340  mm,
	W =  163.672 deg,	P =    1.149 deg,	R =   89.663 deg
};
P[177]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.681  mm,	Y =   20.464  mm,	Z =  355.392  mm,
	W =  163.920 deg,	P =    0.759 deg,	R =   89.781 deg
};
P[178]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.680  mm,	Y =   17.490  mm,	Z =  355.425  mm,
	W =  164.215 deg,	P =    0.400 deg,	R =   89.887 deg
};
P[179]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.675  mm,	Y =   14.515  mm,	Z =  355.436  mm,
	W =  164.533 deg,	P =    0.056 deg,	R =   89.985 deg
};
P[180]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.669  mm,	Y =   11.539  mm,	Z =  355.429  mm,
	W =  164.900 deg,	P =   -0.273 deg,	R =   90.074 deg
};
P[181]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.663  mm,	Y =    8.562  mm,	Z =  355.403  mm,
	W =  165.267 deg,	P =   -0.589 deg,	R =   90.155 deg
};
P[182]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.649  mm,	Y =    5.583  mm,	Z =  355.358  mm,
	W =  165.682 deg,	P =   -0.881 deg,	R =   90.225 deg
};
P[183]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.631  mm,	Y =    2.604  mm,	Z =  355.298  mm,
	W =  166.099 deg,	P =   -1.165 deg,	R =   90.288 deg
};
P[184]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.619  mm,	Y =   -0.378  mm,	Z =  355.224  mm,
	W =  166.517 deg,	P =   -1.413 deg,	R =   90.339 deg
};
P[185]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.610  mm,	Y =   -3.359  mm,	Z =  355.137  mm,
	W =  166.943 deg,	P =   -1.655 deg,	R =   90.384 deg
};
P[186]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.597  mm,	Y =   -6.343  mm,	Z =  355.038  mm,
	W =  167.358 deg,	P =   -1.867 deg,	R =   90.419 deg
};
P[187]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.586  mm,	Y =   -9.327  mm,	Z =  354.928  mm,
	W =  167.761 deg,	P =   -2.064 deg,	R =   90.448 deg
};
P[188]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.575  mm,	Y =  -12.312  mm,	Z =  354.808  mm,
	W =  168.149 deg,	P =   -2.248 deg,	R =   90.472 deg
};
P[189]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.563  mm,	Y =  -15.299  mm,	Z =  354.679  mm,
	W =  168.505 deg,	P =   -2.395 deg,	R =   90.487 deg
};
P[190]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.553  mm,	Y =  -18.286  mm,	Z =  354.543  mm,
	W =  168.830 deg,	P =   -2.541 deg,	R =   90.502 deg
};
P[191]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.542  mm,	Y =  -21.275  mm,	Z =  354.400  mm,
	W =  169.127 deg,	P =   -2.654 deg,	R =   90.510 deg
};
P[192]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.533  mm,	Y =  -24.264  mm,	Z =  354.252  mm,
	W =  169.364 deg,	P =   -2.766 deg,	R =   90.519 deg
};
P[193]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.524  mm,	Y =  -27.254  mm,	Z =  354.098  mm,
	W =  169.591 deg,	P =   -2.856 deg,	R =   90.524 deg
};
P[194]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.519  mm,	Y =  -30.243  mm,	Z =  353.940  mm,
	W =  169.720 deg,	P =   -2.943 deg,	R =   90.533 deg
};
P[195]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.515  mm,	Y =  -33.233  mm,	Z =  353.779  mm,
	W =  169.818 deg,	P =   -3.025 deg,	R =   90.543 deg
};
P[196]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.511  mm,	Y =  -36.224  mm,	Z =  353.613  mm,
	W =  169.875 deg,	P =   -3.090 deg,	R =   90.552 deg
};
P[197]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.511  mm,	Y =  -39.214  mm,	Z =  353.444  mm,
	W =  169.853 deg,	P =   -3.164 deg,	R =   90.566 deg
};
P[198]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.510  mm,	Y =  -42.204  mm,	Z =  353.272  mm,
	W =  169.818 deg,	P =   -3.230 deg,	R =   90.580 deg
};
P[199]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.514  mm,	Y =  -45.193  mm,	Z =  353.096  mm,
	W =  169.676 deg,	P =   -3.309 deg,	R =   90.602 deg
};
P[200]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.518  mm,	Y =  -48.182  mm,	Z =  352.915  mm,
	W =  169.509 deg,	P =   -3.389 deg,	R =   90.627 deg
};
P[201]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.524  mm,	Y =  -51.170  mm,	Z =  352.731  mm,
	W =  169.300 deg,	P =   -3.479 deg,	R =   90.657 deg
};
P[202]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.531  mm,	Y =  -54.156  mm,	Z =  352.541  mm,
	W =  169.028 deg,	P =   -3.580 deg,	R =   90.694 deg
};
P[203]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.538  mm,	Y =  -57.141  mm,	Z =  352.346  mm,
	W =  168.744 deg,	P =   -3.692 deg,	R =   90.734 deg
};
P[204]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.547  mm,	Y =  -60.124  mm,	Z =  352.144  mm,
	W =  168.389 deg,	P =   -3.824 deg,	R =   90.785 deg
};
P[205]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.557  mm,	Y =  -63.104  mm,	Z =  351.934  mm,
	W =  168.018 deg,	P =   -3.992 deg,	R =   90.846 deg
};
P[206]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.566  mm,	Y =  -66.085  mm,	Z =  351.715  mm,
	W =  167.629 deg,	P =   -4.134 deg,	R =   90.906 deg
};
P[207]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.576  mm,	Y =  -69.062  mm,	Z =  351.486  mm,
	W =  167.212 deg,	P =   -4.312 deg,	R =   90.978 deg
};
P[208]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.586  mm,	Y =  -72.037  mm,	Z =  351.247  mm,
	W =  166.795 deg,	P =   -4.517 deg,	R =   91.059 deg
};
P[209]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.594  mm,	Y =  -75.009  mm,	Z =  350.995  mm,
	W =  166.361 deg,	P =   -4.736 deg,	R =   91.148 deg
};
P[210]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.605  mm,	Y =  -77.979  mm,	Z =  350.730  mm,
	W =  165.930 deg,	P =   -4.979 deg,	R =   91.246 deg
};
P[211]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.612  mm,	Y =  -80.946  mm,	Z =  350.449  mm,
	W =  165.514 deg,	P =   -5.234 deg,	R =   91.350 deg
};
P[212]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.620  mm,	Y =  -83.911  mm,	Z =  350.154  mm,
	W =  165.107 deg,	P =   -5.500 deg,	R =   91.460 deg
};
P[213]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.627  mm,	Y =  -86.871  mm,	Z =  349.842  mm,
	W =  164.720 deg,	P =   -5.802 deg,	R =   91.582 deg
};
P[214]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.633  mm,	Y =  -89.829  mm,	Z =  349.512  mm,
	W =  164.365 deg,	P =   -6.104 deg,	R =   91.705 deg
};
P[215]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.642  mm,	Y =  -92.783  mm,	Z =  349.164  mm,
	W =  164.023 deg,	P =   -6.433 deg,	R =   91.837 deg
};
P[216]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.643  mm,	Y =  -95.735  mm,	Z =  348.795  mm,
	W =  163.743 deg,	P =   -6.765 deg,	R =   91.967 deg
};
P[217]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.650  mm,	Y =  -98.684  mm,	Z =  348.408  mm,
	W =  163.487 deg,	P =   -7.102 deg,	R =   92.099 deg
};
P[218]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.653  mm,	Y = -101.627  mm,	Z =  347.999  mm,
	W =  163.274 deg,	P =   -7.474 deg,	R =   92.238 deg
};
P[219]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.656  mm,	Y = -104.569  mm,	Z =  347.569  mm,
	W =  163.117 deg,	P =   -7.833 deg,	R =   92.368 deg
};
P[220]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.660  mm,	Y = -107.506  mm,	Z =  347.118  mm,
	W =  162.982 deg,	P =   -8.217 deg,	R =   92.505 deg
};
P[221]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.660  mm,	Y = -110.441  mm,	Z =  346.645  mm,
	W =  162.933 deg,	P =   -8.591 deg,	R =   92.626 deg
};
P[222]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.664  mm,	Y = -113.373  mm,	Z =  346.151  mm,
	W =  162.915 deg,	P =   -8.951 deg,	R =   92.738 deg
};
P[223]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.663  mm,	Y = -116.298  mm,	Z =  345.635  mm,
	W =  162.943 deg,	P =   -9.365 deg,	R =   92.858 deg
};
P[224]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.665  mm,	Y = -119.222  mm,	Z =  345.098  mm,
	W =  163.029 deg,	P =   -9.748 deg,	R =   92.958 deg
};
P[225]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.663  mm,	Y = -122.141  mm,	Z =  344.539  mm,
	W =  163.147 deg,	P =  -10.140 deg,	R =   93.053 deg
};
P[226]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.661  mm,	Y = -125.058  mm,	Z =  343.960  mm,
	W =  163.336 deg,	P =  -10.519 deg,	R =   93.128 deg
};
P[227]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.659  mm,	Y = -127.971  mm,	Z =  343.360  mm,
	W =  163.533 deg,	P =  -10.901 deg,	R =   93.200 deg
};
P[228]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.655  mm,	Y = -130.882  mm,	Z =  342.741  mm,
	W =  163.813 deg,	P =  -11.267 deg,	R =   93.246 deg
};
P[229]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.652  mm,	Y = -133.791  mm,	Z =  342.104  mm,
	W =  164.112 deg,	P =  -11.604 deg,	R =   93.277 deg
};
P[230]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  390.644  mm,	Y = -136.693  mm,	Z =  341.448  mm,
	W =  164.434 deg,	P =  -11.977 deg,	R =   93.309 deg
};
P[231]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  391.830  mm,	Y = -139.384  mm,	Z =  341.140  mm,
	W =  164.940 deg,	P =  -12.463 deg,	R =   93.323 deg
};
P[232]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  394.706  mm,	Y = -139.380  mm,	Z =  341.883  mm,
	W =  165.359 deg,	P =  -12.863 deg,	R =   93.329 deg
};
P[233]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  397.587  mm,	Y = -139.369  mm,	Z =  342.607  mm,
	W =  165.782 deg,	P =  -13.265 deg,	R =   93.327 deg
};
P[234]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.473  mm,	Y = -139.360  mm,	Z =  343.308  mm,
	W =  166.212 deg,	P =  -13.660 deg,	R =   93.317 deg
};
P[235]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.365  mm,	Y = -139.356  mm,	Z =  343.986  mm,
	W =  166.649 deg,	P =  -14.055 deg,	R =   93.299 deg
};
P[236]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  406.261  mm,	Y = -139.342  mm,	Z =  344.643  mm,
	W =  167.090 deg,	P =  -14.441 deg,	R =   93.272 deg
};
P[237]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  409.162  mm,	Y = -139.345  mm,	Z =  345.273  mm,
	W =  167.540 deg,	P =  -14.826 deg,	R =   93.236 deg
};
P[238]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  412.067  mm,	Y = -139.333  mm,	Z =  345.884  mm,
	W =  167.999 deg,	P =  -15.202 deg,	R =   93.191 deg
};
P[239]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  414.978  mm,	Y = -139.331  mm,	Z =  346.469  mm,
	W =  168.458 deg,	P =  -15.569 deg,	R =   93.138 deg
};
P[240]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  417.893  mm,	Y = -139.327  mm,	Z =  347.030  mm,
	W =  168.924 deg,	P =  -15.934 deg,	R =   93.076 deg
};
P[241]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.812  mm,	Y = -139.319  mm,	Z =  347.569  mm,
	W =  169.400 deg,	P =  -16.279 deg,	R =   93.003 deg
};
P[242]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.736  mm,	Y = -139.323  mm,	Z =  348.079  mm,
	W =  169.881 deg,	P =  -16.623 deg,	R =   92.923 deg
};
P[243]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  426.662  mm,	Y = -139.310  mm,	Z =  348.570  mm,
	W =  170.369 deg,	P =  -16.948 deg,	R =   92.832 deg
};
P[244]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  429.594  mm,	Y = -139.314  mm,	Z =  349.031  mm,
	W =  170.862 deg,	P =  -17.267 deg,	R =   92.733 deg
};
P[245]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  432.529  mm,	Y = -139.310  mm,	Z =  349.470  mm,
	W =  171.358 deg,	P =  -17.578 deg,	R =   92.628 deg
};
P[246]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  435.467  mm,	Y = -139.307  mm,	Z =  349.883  mm,
	W =  171.868 deg,	P =  -17.858 deg,	R =   92.509 deg
};
P[247]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  438.409  mm,	Y = -139.310  mm,	Z =  350.269  mm,
	W =  172.376 deg,	P =  -18.140 deg,	R =   92.386 deg
};
P[248]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.353  mm,	Y = -139.302  mm,	Z =  350.633  mm,
	W =  172.896 deg,	P =  -18.393 deg,	R =   92.252 deg
};
P[249]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.301  mm,	Y = -139.307  mm,	Z =  350.966  mm,
	W =  173.416 deg,	P =  -18.640 deg,	R =   92.113 deg
};
P[250]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  447.250  mm,	Y = -139.302  mm,	Z =  351.277  mm,
	W =  173.956 deg,	P =  -18.865 deg,	R =   91.961 deg
};
P[251]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  450.204  mm,	Y = -139.303  mm,	Z =  351.560  mm,
	W =  174.475 deg,	P =  -19.074 deg,	R =   91.810 deg
};
P[252]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  453.159  mm,	Y = -139.305  mm,	Z =  351.816  mm,
	W =  175.007 deg,	P =  -19.273 deg,	R =   91.652 deg
};
P[253]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  456.116  mm,	Y = -139.301  mm,	Z =  352.047  mm,
	W =  175.552 deg,	P =  -19.437 deg,	R =   91.483 deg
};
P[254]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.075  mm,	Y = -139.304  mm,	Z =  352.250  mm,
	W =  176.092 deg,	P =  -19.596 deg,	R =   91.312 deg
};
P[255]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.036  mm,	Y = -139.301  mm,	Z =  352.428  mm,
	W =  176.644 deg,	P =  -19.726 deg,	R =   91.134 deg
};
P[256]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.998  mm,	Y = -139.304  mm,	Z =  352.577  mm,
	W =  177.190 deg,	P =  -19.842 deg,	R =   90.954 deg
};
P[257]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.961  mm,	Y = -139.304  mm,	Z =  352.700  mm,
	W =  177.752 deg,	P =  -19.935 deg,	R =   90.767 deg
};
P[258]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.925  mm,	Y = -139.303  mm,	Z =  352.796  mm,
	W =  178.297 deg,	P =  -20.008 deg,	R =   90.583 deg
};
P[259]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.891  mm,	Y = -139.305  mm,	Z =  352.865  mm,
	W =  178.848 deg,	P =  -20.068 deg,	R =   90.395 deg
};
P[260]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.856  mm,	Y = -139.303  mm,	Z =  352.908  mm,
	W =  179.411 deg,	P =  -20.094 deg,	R =   90.202 deg
};
P[261]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.822  mm,	Y = -139.306  mm,	Z =  352.922  mm,
	W =  179.963 deg,	P =  -20.109 deg,	R =   90.013 deg
};
P[262]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.786  mm,	Y = -139.304  mm,	Z =  352.911  mm,
	W = -179.465 deg,	P =  -20.097 deg,	R =   89.816 deg
};
P[263]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.753  mm,	Y = -139.308  mm,	Z =  352.871  mm,
	W = -178.922 deg,	P =  -20.067 deg,	R =   89.630 deg
};
P[264]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.718  mm,	Y = -139.308  mm,	Z =  352.804  mm,
	W = -178.371 deg,	P =  -20.024 deg,	R =   89.442 deg
};
P[265]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  491.682  mm,	Y = -139.310  mm,	Z =  352.711  mm,
	W = -177.811 deg,	P =  -19.945 deg,	R =   89.253 deg
};
P[266]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  494.646  mm,	Y = -139.312  mm,	Z =  352.590  mm,
	W = -177.263 deg,	P =  -19.856 deg,	R =   89.070 deg
};
P[267]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  497.607  mm,	Y = -139.313  mm,	Z =  352.443  mm,
	W = -176.707 deg,	P =  -19.742 deg,	R =   88.887 deg
};
P[268]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.569  mm,	Y = -139.315  mm,	Z =  352.269  mm,
	W = -176.165 deg,	P =  -19.610 deg,	R =   88.711 deg
};
P[269]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  503.527  mm,	Y = -139.316  mm,	Z =  352.068  mm,
	W = -175.613 deg,	P =  -19.457 deg,	R =   88.536 deg
};
P[270]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.485  mm,	Y = -139.319  mm,	Z =  351.840  mm,
	W = -175.079 deg,	P =  -19.287 deg,	R =   88.371 deg
};
P[271]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.441  mm,	Y = -139.319  mm,	Z =  351.586  mm,
	W = -174.546 deg,	P =  -19.103 deg,	R =   88.210 deg
};
P[272]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  512.393  mm,	Y = -139.324  mm,	Z =  351.305  mm,
	W = -174.009 deg,	P =  -18.892 deg,	R =   88.054 deg
};
P[273]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  515.344  mm,	Y = -139.323  mm,	Z =  350.999  mm,
	W = -173.485 deg,	P =  -18.668 deg,	R =   87.907 deg
};
P[274]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  518.291  mm,	Y = -139.327  mm,	Z =  350.666  mm,
	W = -172.951 deg,	P =  -18.425 deg,	R =   87.762 deg
};
P[275]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  521.237  mm,	Y = -139.330  mm,	Z =  350.307  mm,
	W = -172.445 deg,	P =  -18.167 deg,	R =   87.632 deg
};
P[276]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  524.179  mm,	Y = -139.330  mm,	Z =  349.924  mm,
	W = -171.935 deg,	P =  -17.899 deg,	R =   87.506 deg
};
P[277]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.117  mm,	Y = -139.338  mm,	Z =  349.512  mm,
	W = -171.426 deg,	P =  -17.606 deg,	R =   87.389 deg
};
P[278]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.053  mm,	Y = -139.335  mm,	Z =  349.079  mm,
	W = -170.928 deg,	P =  -17.306 deg,	R =   87.281 deg
};
P[279]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  532.984  mm,	Y = -139.344  mm,	Z =  348.617  mm,
	W = -170.430 deg,	P =  -16.990 deg,	R =   87.180 deg
};
P[280]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  535.912  mm,	Y = -139.346  mm,	Z =  348.132  mm,
	W = -169.945 deg,	P =  -16.662 deg,	R =   87.090 deg
};
P[281]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  538.836  mm,	Y = -139.348  mm,	Z =  347.623  mm,
	W = -169.456 deg,	P =  -16.320 deg,	R =   87.006 deg
};
P[282]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  541.756  mm,	Y = -139.358  mm,	Z =  347.087  mm,
	W = -168.987 deg,	P =  -15.973 deg,	R =   86.934 deg
};
P[283]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.671  mm,	Y = -139.355  mm,	Z =  346.530  mm,
	W = -168.519 deg,	P =  -15.616 deg,	R =   86.870 deg
};
P[284]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.582  mm,	Y = -139.369  mm,	Z =  345.946  mm,
	W = -168.055 deg,	P =  -15.247 deg,	R =   86.816 deg
};
P[285]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.488  mm,	Y = -139.370  mm,	Z =  345.341  mm,
	W = -167.600 deg,	P =  -14.872 deg,	R =   86.770 deg
};
P[286]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  553.390  mm,	Y = -139.377  mm,	Z =  344.711  mm,
	W = -167.148 deg,	P =  -14.489 deg,	R =   86.733 deg
};
P[287]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  556.287  mm,	Y = -139.386  mm,	Z =  344.058  mm,
	W = -166.707 deg,	P =  -14.101 deg,	R =   86.706 deg
};
P[288]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  559.179  mm,	Y = -139.387  mm,	Z =  343.384  mm,
	W = -166.269 deg,	P =  -13.710 deg,	R =   86.686 deg
};
P[289]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  562.065  mm,	Y = -139.404  mm,	Z =  342.684  mm,
	W = -165.839 deg,	P =  -13.311 deg,	R =   86.675 deg
};
P[290]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.948  mm,	Y = -139.403  mm,	Z =  341.966  mm,
	W = -165.414 deg,	P =  -12.912 deg,	R =   86.672 deg
};
P[291]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.827  mm,	Y = -139.306  mm,	Z =  341.248  mm,
	W = -164.980 deg,	P =  -12.497 deg,	R =   86.677 deg
};
P[292]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.391  mm,	Y = -136.809  mm,	Z =  341.412  mm,
	W = -164.452 deg,	P =  -11.983 deg,	R =   86.694 deg
};
P[293]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.371  mm,	Y = -133.904  mm,	Z =  342.072  mm,
	W = -164.119 deg,	P =  -11.647 deg,	R =   86.713 deg
};
P[294]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.373  mm,	Y = -130.998  mm,	Z =  342.708  mm,
	W = -163.822 deg,	P =  -11.272 deg,	R =   86.754 deg
};
P[295]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.363  mm,	Y = -128.087  mm,	Z =  343.330  mm,
	W = -163.564 deg,	P =  -10.911 deg,	R =   86.804 deg
};
P[296]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.357  mm,	Y = -125.175  mm,	Z =  343.931  mm,
	W = -163.332 deg,	P =  -10.522 deg,	R =   86.870 deg
};
P[297]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.355  mm,	Y = -122.258  mm,	Z =  344.511  mm,
	W = -163.166 deg,	P =  -10.147 deg,	R =   86.949 deg
};
P[298]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.346  mm,	Y = -119.337  mm,	Z =  345.073  mm,
	W = -163.032 deg,	P =   -9.778 deg,	R =   87.034 deg
};
P[299]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.283  mm,	Y = -116.419  mm,	Z =  345.629  mm,
	W = -162.957 deg,	P =   -9.374 deg,	R =   87.142 deg
};
P[300]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.210  mm,	Y = -113.497  mm,	Z =  346.168  mm,
	W = -162.933 deg,	P =   -8.995 deg,	R =   87.252 deg
};
P[301]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.143  mm,	Y = -110.571  mm,	Z =  346.683  mm,
	W = -162.950 deg,	P =   -8.600 deg,	R =   87.374 deg
};
P[302]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.073  mm,	Y = -107.641  mm,	Z =  347.178  mm,
	W = -163.036 deg,	P =   -8.222 deg,	R =   87.502 deg
};
P[303]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  569.007  mm,	Y = -104.709  mm,	Z =  347.649  mm,
	W = -163.137 deg,	P =   -7.835 deg,	R =   87.634 deg
};
P[304]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.935  mm,	Y = -101.772  mm,	Z =  348.100  mm,
	W = -163.331 deg,	P =   -7.465 deg,	R =   87.772 deg
};
P[305]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.873  mm,	Y =  -98.830  mm,	Z =  348.528  mm,
	W = -163.546 deg,	P =   -7.129 deg,	R =   87.901 deg
};
P[306]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.805  mm,	Y =  -95.888  mm,	Z =  348.935  mm,
	W = -163.803 deg,	P =   -6.738 deg,	R =   88.048 deg
};
P[307]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.738  mm,	Y =  -92.942  mm,	Z =  349.321  mm,
	W = -164.111 deg,	P =   -6.385 deg,	R =   88.187 deg
};
P[308]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.681  mm,	Y =  -89.991  mm,	Z =  349.684  mm,
	W = -164.450 deg,	P =   -6.054 deg,	R =   88.319 deg
};
P[309]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.605  mm,	Y =  -87.038  mm,	Z =  350.032  mm,
	W = -164.815 deg,	P =   -5.727 deg,	R =   88.449 deg
};
P[310]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.554  mm,	Y =  -84.080  mm,	Z =  350.354  mm,
	W = -165.210 deg,	P =   -5.423 deg,	R =   88.571 deg
};
P[311]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.487  mm,	Y =  -81.120  mm,	Z =  350.663  mm,
	W = -165.627 deg,	P =   -5.133 deg,	R =   88.687 deg
};
P[312]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.426  mm,	Y =  -78.157  mm,	Z =  350.954  mm,
	W = -166.051 deg,	P =   -4.848 deg,	R =   88.797 deg
};
P[313]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.372  mm,	Y =  -75.189  mm,	Z =  351.228  mm,
	W = -166.491 deg,	P =   -4.613 deg,	R =   88.893 deg
};
P[314]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.302  mm,	Y =  -72.220  mm,	Z =  351.490  mm,
	W = -166.936 deg,	P =   -4.379 deg,	R =   88.985 deg
};
P[315]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.254  mm,	Y =  -69.247  mm,	Z =  351.735  mm,
	W = -167.361 deg,	P =   -4.172 deg,	R =   89.065 deg
};
P[316]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.190  mm,	Y =  -66.272  mm,	Z =  351.971  mm,
	W = -167.789 deg,	P =   -3.989 deg,	R =   89.138 deg
};
P[317]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.131  mm,	Y =  -63.295  mm,	Z =  352.196  mm,
	W = -168.187 deg,	P =   -3.815 deg,	R =   89.203 deg
};
P[318]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.077  mm,	Y =  -60.314  mm,	Z =  352.410  mm,
	W = -168.567 deg,	P =   -3.682 deg,	R =   89.256 deg
};
P[319]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  568.011  mm,	Y =  -57.333  mm,	Z =  352.619  mm,
	W = -168.912 deg,	P =   -3.540 deg,	R =   89.307 deg
};
P[320]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.958  mm,	Y =  -54.348  mm,	Z =  352.819  mm,
	W = -169.226 deg,	P =   -3.452 deg,	R =   89.344 deg
};
P[321]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.895  mm,	Y =  -51.361  mm,	Z =  353.014  mm,
	W = -169.511 deg,	P =   -3.379 deg,	R =   89.375 deg
};
P[322]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.834  mm,	Y =  -48.375  mm,	Z =  353.205  mm,
	W = -169.729 deg,	P =   -3.288 deg,	R =   89.405 deg
};
P[323]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.772  mm,	Y =  -45.385  mm,	Z =  353.392  mm,
	W = -169.910 deg,	P =   -3.247 deg,	R =   89.422 deg
};
P[324]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.706  mm,	Y =  -42.397  mm,	Z =  353.577  mm,
	W = -170.035 deg,	P =   -3.176 deg,	R =   89.442 deg
};
P[325]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.642  mm,	Y =  -39.405  mm,	Z =  353.759  mm,
	W = -170.109 deg,	P =   -3.153 deg,	R =   89.451 deg
};
P[326]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.575  mm,	Y =  -36.412  mm,	Z =  353.939  mm,
	W = -170.145 deg,	P =   -3.136 deg,	R =   89.455 deg
};
P[327]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.507  mm,	Y =  -33.423  mm,	Z =  354.118  mm,
	W = -170.098 deg,	P =   -3.071 deg,	R =   89.464 deg
};
P[328]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.435  mm,	Y =  -30.430  mm,	Z =  354.295  mm,
	W = -170.015 deg,	P =   -3.052 deg,	R =   89.463 deg
};
P[329]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.368  mm,	Y =  -27.440  mm,	Z =  354.470  mm,
	W = -169.874 deg,	P =   -2.986 deg,	R =   89.467 deg
};
P[330]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.290  mm,	Y =  -24.449  mm,	Z =  354.644  mm,
	W = -169.684 deg,	P =   -2.941 deg,	R =   89.465 deg
};
P[331]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.221  mm,	Y =  -21.458  mm,	Z =  354.814  mm,
	W = -169.452 deg,	P =   -2.876 deg,	R =   89.465 deg
};
P[332]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.147  mm,	Y =  -18.470  mm,	Z =  354.981  mm,
	W = -169.174 deg,	P =   -2.781 deg,	R =   89.468 deg
};
P[333]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.068  mm,	Y =  -15.481  mm,	Z =  355.145  mm,
	W = -168.864 deg,	P =   -2.691 deg,	R =   89.470 deg
};
P[334]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  567.004  mm,	Y =  -12.494  mm,	Z =  355.299  mm,
	W = -168.519 deg,	P =   -2.564 deg,	R =   89.479 deg
};
P[335]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.916  mm,	Y =   -9.509  mm,	Z =  355.453  mm,
	W = -168.146 deg,	P =   -2.410 deg,	R =   89.494 deg
};
P[336]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.852  mm,	Y =   -6.524  mm,	Z =  355.594  mm,
	W = -167.757 deg,	P =   -2.246 deg,	R =   89.513 deg
};
P[337]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.776  mm,	Y =   -3.541  mm,	Z =  355.727  mm,
	W = -167.350 deg,	P =   -2.036 deg,	R =   89.543 deg
};
P[338]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.697  mm,	Y =   -0.559  mm,	Z =  355.851  mm,
	W = -166.945 deg,	P =   -1.821 deg,	R =   89.578 deg
};
P[339]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.638  mm,	Y =    2.421  mm,	Z =  355.958  mm,
	W = -166.528 deg,	P =   -1.565 deg,	R =   89.625 deg
};
P[340]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.549  mm,	Y =    5.398  mm,	Z =  356.058  mm,
	W = -166.123 deg,	P =   -1.281 deg,	R =   89.684 deg
};
P[341]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.490  mm,	Y =    8.377  mm,	Z =  356.136  mm,
	W = -165.734 deg,	P =   -0.998 deg,	R =   89.746 deg
};
P[342]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.402  mm,	Y =   11.351  mm,	Z =  356.205  mm,
	W = -165.362 deg,	P =   -0.656 deg,	R =   89.829 deg
};
P[343]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.333  mm,	Y =   14.326  mm,	Z =  356.250  mm,
	W = -165.018 deg,	P =   -0.310 deg,	R =   89.917 deg
};
P[344]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.261  mm,	Y =   17.299  mm,	Z =  356.276  mm,
	W = -164.697 deg,	P =    0.055 deg,	R =   90.015 deg
};
P[345]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.197  mm,	Y =   20.268  mm,	Z =  356.280  mm,
	W = -164.409 deg,	P =    0.471 deg,	R =   90.131 deg
};
P[346]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.127  mm,	Y =   23.241  mm,	Z =  356.263  mm,
	W = -164.170 deg,	P =    0.846 deg,	R =   90.240 deg
};
P[347]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  566.061  mm,	Y =   26.207  mm,	Z =  356.222  mm,
	W = -163.968 deg,	P =    1.293 deg,	R =   90.371 deg
};
P[348]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.995  mm,	Y =   29.175  mm,	Z =  356.157  mm,
	W = -163.814 deg,	P =    1.723 deg,	R =   90.500 deg
};
P[349]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.927  mm,	Y =   32.141  mm,	Z =  356.067  mm,
	W = -163.704 deg,	P =    2.162 deg,	R =   90.632 deg
};
P[350]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.860  mm,	Y =   35.103  mm,	Z =  355.952  mm,
	W = -163.643 deg,	P =    2.639 deg,	R =   90.774 deg
};
P[351]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.790  mm,	Y =   38.067  mm,	Z =  355.812  mm,
	W = -163.634 deg,	P =    3.075 deg,	R =   90.903 deg
};
P[352]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.726  mm,	Y =   41.026  mm,	Z =  355.644  mm,
	W = -163.678 deg,	P =    3.560 deg,	R =   91.042 deg
};
P[353]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.655  mm,	Y =   43.986  mm,	Z =  355.453  mm,
	W = -163.771 deg,	P =    4.014 deg,	R =   91.167 deg
};
P[354]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.594  mm,	Y =   46.945  mm,	Z =  355.232  mm,
	W = -163.911 deg,	P =    4.467 deg,	R =   91.287 deg
};
P[355]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.518  mm,	Y =   49.900  mm,	Z =  354.991  mm,
	W = -164.096 deg,	P =    4.936 deg,	R =   91.404 deg
};
P[356]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.453  mm,	Y =   52.857  mm,	Z =  354.721  mm,
	W = -164.328 deg,	P =    5.354 deg,	R =   91.500 deg
};
P[357]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.388  mm,	Y =   55.809  mm,	Z =  354.428  mm,
	W = -164.593 deg,	P =    5.817 deg,	R =   91.600 deg
};
P[358]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.313  mm,	Y =   58.762  mm,	Z =  354.114  mm,
	W = -164.911 deg,	P =    6.229 deg,	R =   91.676 deg
};
P[359]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.259  mm,	Y =   61.715  mm,	Z =  353.772  mm,
	W = -165.254 deg,	P =    6.619 deg,	R =   91.738 deg
};
P[360]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.175  mm,	Y =   64.665  mm,	Z =  353.418  mm,
	W = -165.622 deg,	P =    7.008 deg,	R =   91.791 deg
};
P[361]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.119  mm,	Y =   67.617  mm,	Z =  353.036  mm,
	W = -166.016 deg,	P =    7.349 deg,	R =   91.825 deg
};
P[362]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  565.049  mm,	Y =   70.566  mm,	Z =  352.640  mm,
	W = -166.420 deg,	P =    7.689 deg,	R =   91.851 deg
};
P[363]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.978  mm,	Y =   73.515  mm,	Z =  352.228  mm,
	W = -166.844 deg,	P =    8.000 deg,	R =   91.863 deg
};
P[364]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.926  mm,	Y =   76.466  mm,	Z =  351.797  mm,
	W = -167.262 deg,	P =    8.259 deg,	R =   91.860 deg
};
P[365]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.844  mm,	Y =   79.416  mm,	Z =  351.358  mm,
	W = -167.688 deg,	P =    8.507 deg,	R =   91.849 deg
};
P[366]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.794  mm,	Y =   82.367  mm,	Z =  350.902  mm,
	W = -168.101 deg,	P =    8.710 deg,	R =   91.828 deg
};
P[367]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.724  mm,	Y =   85.319  mm,	Z =  350.440  mm,
	W = -168.496 deg,	P =    8.888 deg,	R =   91.801 deg
};
P[368]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.660  mm,	Y =   88.270  mm,	Z =  349.968  mm,
	W = -168.875 deg,	P =    9.052 deg,	R =   91.772 deg
};
P[369]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.602  mm,	Y =   91.225  mm,	Z =  349.489  mm,
	W = -169.223 deg,	P =    9.148 deg,	R =   91.733 deg
};
P[370]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.529  mm,	Y =   94.179  mm,	Z =  349.007  mm,
	W = -169.536 deg,	P =    9.246 deg,	R =   91.700 deg
};
P[371]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.475  mm,	Y =   97.135  mm,	Z =  348.518  mm,
	W = -169.824 deg,	P =    9.298 deg,	R =   91.661 deg
};
P[372]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.406  mm,	Y =  100.092  mm,	Z =  348.029  mm,
	W = -170.047 deg,	P =    9.340 deg,	R =   91.631 deg
};
P[373]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.345  mm,	Y =  103.050  mm,	Z =  347.538  mm,
	W = -170.262 deg,	P =    9.357 deg,	R =   91.598 deg
};
P[374]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.278  mm,	Y =  106.009  mm,	Z =  347.048  mm,
	W = -170.378 deg,	P =    9.357 deg,	R =   91.579 deg
};
P[375]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.212  mm,	Y =  108.969  mm,	Z =  346.557  mm,
	W = -170.465 deg,	P =    9.347 deg,	R =   91.563 deg
};
P[376]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.146  mm,	Y =  111.930  mm,	Z =  346.068  mm,
	W = -170.510 deg,	P =    9.324 deg,	R =   91.551 deg
};
P[377]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.078  mm,	Y =  114.891  mm,	Z =  345.580  mm,
	W = -170.480 deg,	P =    9.296 deg,	R =   91.552 deg
};
P[378]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  564.012  mm,	Y =  117.852  mm,	Z =  345.094  mm,
	W = -170.433 deg,	P =    9.272 deg,	R =   91.555 deg
};
P[379]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  562.656  mm,	Y =  120.524  mm,	Z =  344.872  mm,
	W = -170.490 deg,	P =    9.179 deg,	R =   91.531 deg
};
P[380]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  560.548  mm,	Y =  122.657  mm,	Z =  344.866  mm,
	W = -170.652 deg,	P =    9.058 deg,	R =   91.485 deg
};
P[381]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  558.440  mm,	Y =  124.795  mm,	Z =  344.859  mm,
	W = -170.818 deg,	P =    8.870 deg,	R =   91.428 deg
};
P[382]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  556.328  mm,	Y =  126.933  mm,	Z =  344.856  mm,
	W = -170.929 deg,	P =    8.667 deg,	R =   91.378 deg
};
P[383]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  554.218  mm,	Y =  129.075  mm,	Z =  344.856  mm,
	W = -171.041 deg,	P =    8.426 deg,	R =   91.323 deg
};
P[384]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  552.104  mm,	Y =  131.216  mm,	Z =  344.864  mm,
	W = -171.130 deg,	P =    8.183 deg,	R =   91.272 deg
};
P[385]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.922  mm,	Y =  133.287  mm,	Z =  344.899  mm,
	W = -171.223 deg,	P =    7.931 deg,	R =   91.220 deg
};
P[386]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.985  mm,	Y =  133.216  mm,	Z =  345.347  mm,
	W = -171.635 deg,	P =    7.651 deg,	R =   91.122 deg
};
P[387]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.046  mm,	Y =  133.154  mm,	Z =  345.773  mm,
	W = -172.061 deg,	P =    7.374 deg,	R =   91.025 deg
};
P[388]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  541.101  mm,	Y =  133.089  mm,	Z =  346.179  mm,
	W = -172.448 deg,	P =    7.120 deg,	R =   90.941 deg
};
P[389]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  538.154  mm,	Y =  133.023  mm,	Z =  346.564  mm,
	W = -172.846 deg,	P =    6.864 deg,	R =   90.859 deg
};
P[390]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  535.205  mm,	Y =  132.963  mm,	Z =  346.929  mm,
	W = -173.246 deg,	P =    6.620 deg,	R =   90.782 deg
};
P[391]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  532.253  mm,	Y =  132.895  mm,	Z =  347.274  mm,
	W = -173.634 deg,	P =    6.385 deg,	R =   90.711 deg
};
P[392]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.299  mm,	Y =  132.834  mm,	Z =  347.598  mm,
	W = -174.035 deg,	P =    6.151 deg,	R =   90.641 deg
};
P[393]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.341  mm,	Y =  132.769  mm,	Z =  347.902  mm,
	W = -174.407 deg,	P =    5.945 deg,	R =   90.581 deg
};
P[394]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  523.383  mm,	Y =  132.704  mm,	Z =  348.187  mm,
	W = -174.794 deg,	P =    5.741 deg,	R =   90.522 deg
};
P[395]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  520.421  mm,	Y =  132.642  mm,	Z =  348.453  mm,
	W = -175.165 deg,	P =    5.550 deg,	R =   90.469 deg
};
P[396]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  517.457  mm,	Y =  132.576  mm,	Z =  348.699  mm,
	W = -175.532 deg,	P =    5.374 deg,	R =   90.419 deg
};
P[397]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  514.493  mm,	Y =  132.514  mm,	Z =  348.925  mm,
	W = -175.913 deg,	P =    5.201 deg,	R =   90.371 deg
};
P[398]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.526  mm,	Y =  132.449  mm,	Z =  349.133  mm,
	W = -176.269 deg,	P =    5.057 deg,	R =   90.329 deg
};
P[399]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.559  mm,	Y =  132.383  mm,	Z =  349.322  mm,
	W = -176.636 deg,	P =    4.917 deg,	R =   90.289 deg
};
P[400]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.589  mm,	Y =  132.318  mm,	Z =  349.493  mm,
	W = -176.995 deg,	P =    4.793 deg,	R =   90.251 deg
};
P[401]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  502.618  mm,	Y =  132.251  mm,	Z =  349.644  mm,
	W = -177.344 deg,	P =    4.686 deg,	R =   90.217 deg
};
P[402]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  499.647  mm,	Y =  132.185  mm,	Z =  349.777  mm,
	W = -177.710 deg,	P =    4.587 deg,	R =   90.183 deg
};
P[403]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  496.674  mm,	Y =  132.117  mm,	Z =  349.893  mm,
	W = -178.054 deg,	P =    4.512 deg,	R =   90.153 deg
};
P[404]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  493.701  mm,	Y =  132.049  mm,	Z =  349.989  mm,
	W = -178.409 deg,	P =    4.446 deg,	R =   90.123 deg
};
P[405]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.727  mm,	Y =  131.980  mm,	Z =  350.068  mm,
	W = -178.757 deg,	P =    4.397 deg,	R =   90.095 deg
};
P[406]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  487.753  mm,	Y =  131.911  mm,	Z =  350.129  mm,
	W = -179.100 deg,	P =    4.363 deg,	R =   90.068 deg
};
P[407]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  484.778  mm,	Y =  131.841  mm,	Z =  350.172  mm,
	W = -179.453 deg,	P =    4.342 deg,	R =   90.041 deg
};
P[408]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.803  mm,	Y =  131.770  mm,	Z =  350.197  mm,
	W = -179.788 deg,	P =    4.341 deg,	R =   90.016 deg
};
P[409]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.828  mm,	Y =  131.698  mm,	Z =  350.204  mm,
	W =  179.863 deg,	P =    4.352 deg,	R =   89.990 deg
};
P[410]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.852  mm,	Y =  131.626  mm,	Z =  350.194  mm,
	W =  179.521 deg,	P =    4.380 deg,	R =   89.963 deg
};
P[411]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  472.877  mm,	Y =  131.553  mm,	Z =  350.166  mm,
	W =  179.181 deg,	P =    4.420 deg,	R =   89.937 deg
};
P[412]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  469.902  mm,	Y =  131.480  mm,	Z =  350.120  mm,
	W =  178.832 deg,	P =    4.476 deg,	R =   89.909 deg
};
P[413]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  466.927  mm,	Y =  131.405  mm,	Z =  350.057  mm,
	W =  178.502 deg,	P =    4.546 deg,	R =   89.881 deg
};
P[414]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  463.953  mm,	Y =  131.330  mm,	Z =  349.976  mm,
	W =  178.149 deg,	P =    4.631 deg,	R =   89.851 deg
};
P[415]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.979  mm,	Y =  131.256  mm,	Z =  349.878  mm,
	W =  177.810 deg,	P =    4.731 deg,	R =   89.819 deg
};
P[416]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  458.006  mm,	Y =  131.179  mm,	Z =  349.762  mm,
	W =  177.464 deg,	P =    4.840 deg,	R =   89.786 deg
};
P[417]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  455.034  mm,	Y =  131.104  mm,	Z =  349.628  mm,
	W =  177.113 deg,	P =    4.964 deg,	R =   89.750 deg
};
P[418]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  452.062  mm,	Y =  131.028  mm,	Z =  349.477  mm,
	W =  176.773 deg,	P =    5.099 deg,	R =   89.713 deg
};
P[419]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  449.092  mm,	Y =  130.951  mm,	Z =  349.308  mm,
	W =  176.419 deg,	P =    5.251 deg,	R =   89.672 deg
};
P[420]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  446.122  mm,	Y =  130.876  mm,	Z =  349.121  mm,
	W =  176.077 deg,	P =    5.413 deg,	R =   89.629 deg
};
P[421]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.155  mm,	Y =  130.797  mm,	Z =  348.917  mm,
	W =  175.717 deg,	P =    5.581 deg,	R =   89.583 deg
};
P[422]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.188  mm,	Y =  130.724  mm,	Z =  348.694  mm,
	W =  175.357 deg,	P =    5.761 deg,	R =   89.533 deg
};
P[423]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  437.223  mm,	Y =  130.647  mm,	Z =  348.453  mm,
	W =  175.004 deg,	P =    5.952 deg,	R =   89.481 deg
};
P[424]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  434.260  mm,	Y =  130.570  mm,	Z =  348.195  mm,
	W =  174.639 deg,	P =    6.153 deg,	R =   89.424 deg
};
P[425]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  431.298  mm,	Y =  130.498  mm,	Z =  347.917  mm,
	W =  174.288 deg,	P =    6.363 deg,	R =   89.365 deg
};
P[426]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  428.339  mm,	Y =  130.419  mm,	Z =  347.622  mm,
	W =  173.909 deg,	P =    6.578 deg,	R =   89.300 deg
};
P[427]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.382  mm,	Y =  130.350  mm,	Z =  347.308  mm,
	W =  173.535 deg,	P =    6.798 deg,	R =   89.231 deg
};
P[428]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.426  mm,	Y =  130.275  mm,	Z =  346.975  mm,
	W =  173.163 deg,	P =    7.030 deg,	R =   89.159 deg
};
P[429]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  419.474  mm,	Y =  130.202  mm,	Z =  346.623  mm,
	W =  172.782 deg,	P =    7.264 deg,	R =   89.083 deg
};
P[430]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  416.523  mm,	Y =  130.123  mm,	Z =  346.253  mm,
	W =  172.402 deg,	P =    7.505 deg,	R =   89.002 deg
};
P[431]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  413.576  mm,	Y =  130.057  mm,	Z =  345.863  mm,
	W =  172.012 deg,	P =    7.749 deg,	R =   88.916 deg
};
P[432]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  410.696  mm,	Y =  129.341  mm,	Z =  345.555  mm,
	W =  171.689 deg,	P =    8.002 deg,	R =   88.835 deg
};
P[433]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  408.686  mm,	Y =  127.097  mm,	Z =  345.592  mm,
	W =  171.599 deg,	P =    8.308 deg,	R =   88.777 deg
};
P[434]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  406.680  mm,	Y =  124.855  mm,	Z =  345.637  mm,
	W =  171.500 deg,	P =    8.549 deg,	R =   88.727 deg
};
P[435]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.674  mm,	Y =  122.616  mm,	Z =  345.687  mm,
	W =  171.371 deg,	P =    8.781 deg,	R =   88.673 deg
};
P[436]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.669  mm,	Y =  120.379  mm,	Z =  345.742  mm,
	W =  171.221 deg,	P =    8.977 deg,	R =   88.619 deg
};
P[437]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.668  mm,	Y =  118.144  mm,	Z =  345.799  mm,
	W =  171.044 deg,	P =    9.130 deg,	R =   88.568 deg
};
P[438]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.644  mm,	Y =  115.176  mm,	Z =  346.287  mm,
	W =  171.139 deg,	P =    9.243 deg,	R =   88.566 deg
};
P[439]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.715  mm,	Y =  112.213  mm,	Z =  346.794  mm,
	W =  171.162 deg,	P =    9.347 deg,	R =   88.553 deg
};
P[440]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.779  mm,	Y =  109.250  mm,	Z =  347.306  mm,
	W =  171.180 deg,	P =    9.460 deg,	R =   88.539 deg
};
P[441]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.850  mm,	Y =  106.288  mm,	Z =  347.825  mm,
	W =  171.088 deg,	P =    9.560 deg,	R =   88.508 deg
};
P[442]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.914  mm,	Y =  103.327  mm,	Z =  348.348  mm,
	W =  170.971 deg,	P =    9.658 deg,	R =   88.473 deg
};
P[443]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  400.985  mm,	Y =  100.369  mm,	Z =  348.878  mm,
	W =  170.816 deg,	P =    9.728 deg,	R =   88.435 deg
};
P[444]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.047  mm,	Y =   97.412  mm,	Z =  349.410  mm,
	W =  170.596 deg,	P =    9.787 deg,	R =   88.387 deg
};
P[445]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.113  mm,	Y =   94.458  mm,	Z =  349.945  mm,
	W =  170.364 deg,	P =    9.812 deg,	R =   88.343 deg
};
P[446]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.179  mm,	Y =   91.506  mm,	Z =  350.482  mm,
	W =  170.058 deg,	P =    9.809 deg,	R =   88.289 deg
};
P[447]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.238  mm,	Y =   88.555  mm,	Z =  351.017  mm,
	W =  169.733 deg,	P =    9.776 deg,	R =   88.238 deg
};
P[448]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.310  mm,	Y =   85.608  mm,	Z =  351.554  mm,
	W =  169.382 deg,	P =    9.695 deg,	R =   88.192 deg
};
P[449]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.359  mm,	Y =   82.661  mm,	Z =  352.082  mm,
	W =  169.011 deg,	P =    9.590 deg,	R =   88.147 deg
};
P[450]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.426  mm,	Y =   79.718  mm,	Z =  352.606  mm,
	W =  168.626 deg,	P =    9.422 deg,	R =   88.114 deg
};
P[451]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.482  mm,	Y =   76.775  mm,	Z =  353.121  mm,
	W =  168.227 deg,	P =    9.223 deg,	R =   88.087 deg
};
P[452]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.535  mm,	Y =   73.834  mm,	Z =  353.625  mm,
	W =  167.836 deg,	P =    8.979 deg,	R =   88.073 deg
};
P[453]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.602  mm,	Y =   70.894  mm,	Z =  354.118  mm,
	W =  167.440 deg,	P =    8.685 deg,	R =   88.073 deg
};
P[454]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.643  mm,	Y =   67.951  mm,	Z =  354.591  mm,
	W =  167.060 deg,	P =    8.389 deg,	R =   88.080 deg
};
P[455]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.709  mm,	Y =   65.015  mm,	Z =  355.050  mm,
	W =  166.693 deg,	P =    7.979 deg,	R =   88.119 deg
};
P[456]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.760  mm,	Y =   62.075  mm,	Z =  355.487  mm,
	W =  166.332 deg,	P =    7.568 deg,	R =   88.165 deg
};
P[457]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.813  mm,	Y =   59.135  mm,	Z =  355.902  mm,
	W =  166.031 deg,	P =    7.121 deg,	R =   88.234 deg
};
P[458]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.876  mm,	Y =   56.195  mm,	Z =  356.295  mm,
	W =  165.736 deg,	P =    6.634 deg,	R =   88.318 deg
};
P[459]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.923  mm,	Y =   53.252  mm,	Z =  356.658  mm,
	W =  165.494 deg,	P =    6.133 deg,	R =   88.417 deg
};
P[460]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  401.990  mm,	Y =   50.311  mm,	Z =  356.997  mm,
	W =  165.283 deg,	P =    5.583 deg,	R =   88.536 deg
};
P[461]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.049  mm,	Y =   47.368  mm,	Z =  357.306  mm,
	W =  165.091 deg,	P =    5.018 deg,	R =   88.666 deg
};
P[462]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.110  mm,	Y =   44.422  mm,	Z =  357.583  mm,
	W =  164.999 deg,	P =    4.449 deg,	R =   88.809 deg
};
P[463]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.177  mm,	Y =   41.476  mm,	Z =  357.831  mm,
	W =  164.911 deg,	P =    3.847 deg,	R =   88.964 deg
};
P[464]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.243  mm,	Y =   38.527  mm,	Z =  358.045  mm,
	W =  164.899 deg,	P =    3.262 deg,	R =   89.120 deg
};
P[465]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.312  mm,	Y =   35.578  mm,	Z =  358.227  mm,
	W =  164.919 deg,	P =    2.646 deg,	R =   89.287 deg
};
P[466]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.386  mm,	Y =   32.625  mm,	Z =  358.377  mm,
	W =  164.994 deg,	P =    2.062 deg,	R =   89.447 deg
};
P[467]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.454  mm,	Y =   29.673  mm,	Z =  358.491  mm,
	W =  165.117 deg,	P =    1.449 deg,	R =   89.615 deg
};
P[468]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.533  mm,	Y =   26.719  mm,	Z =  358.576  mm,
	W =  165.271 deg,	P =    0.846 deg,	R =   89.778 deg
};
P[469]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.604  mm,	Y =   23.760  mm,	Z =  358.626  mm,
	W =  165.495 deg,	P =    0.293 deg,	R =   89.924 deg
};
P[470]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.688  mm,	Y =   20.803  mm,	Z =  358.648  mm,
	W =  165.745 deg,	P =   -0.270 deg,	R =   90.069 deg
};
P[471]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.770  mm,	Y =   17.842  mm,	Z =  358.639  mm,
	W =  166.036 deg,	P =   -0.794 deg,	R =   90.197 deg
};
P[472]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.845  mm,	Y =   14.879  mm,	Z =  358.601  mm,
	W =  166.365 deg,	P =   -1.287 deg,	R =   90.312 deg
};
P[473]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  402.937  mm,	Y =   11.916  mm,	Z =  358.539  mm,
	W =  166.717 deg,	P =   -1.761 deg,	R =   90.416 deg
};
P[474]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.006  mm,	Y =    8.948  mm,	Z =  358.448  mm,
	W =  167.098 deg,	P =   -2.172 deg,	R =   90.497 deg
};
P[475]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.095  mm,	Y =    5.980  mm,	Z =  358.338  mm,
	W =  167.497 deg,	P =   -2.561 deg,	R =   90.568 deg
};
P[476]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.164  mm,	Y =    3.008  mm,	Z =  358.205  mm,
	W =  167.904 deg,	P =   -2.899 deg,	R =   90.621 deg
};
P[477]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.242  mm,	Y =    0.033  mm,	Z =  358.056  mm,
	W =  168.325 deg,	P =   -3.182 deg,	R =   90.657 deg
};
P[478]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.335  mm,	Y =   -2.942  mm,	Z =  357.895  mm,
	W =  168.741 deg,	P =   -3.447 deg,	R =   90.686 deg
};
P[479]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.400  mm,	Y =   -5.924  mm,	Z =  357.717  mm,
	W =  169.155 deg,	P =   -3.619 deg,	R =   90.693 deg
};
P[480]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.492  mm,	Y =   -8.906  mm,	Z =  357.534  mm,
	W =  169.552 deg,	P =   -3.770 deg,	R =   90.695 deg
};
P[481]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.565  mm,	Y =  -11.891  mm,	Z =  357.341  mm,
	W =  169.939 deg,	P =   -3.869 deg,	R =   90.686 deg
};
P[482]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.639  mm,	Y =  -14.882  mm,	Z =  357.145  mm,
	W =  170.300 deg,	P =   -3.892 deg,	R =   90.665 deg
};
P[483]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.723  mm,	Y =  -17.872  mm,	Z =  356.948  mm,
	W =  170.625 deg,	P =   -3.930 deg,	R =   90.648 deg
};
P[484]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.787  mm,	Y =  -20.869  mm,	Z =  356.749  mm,
	W =  170.917 deg,	P =   -3.864 deg,	R =   90.617 deg
};
P[485]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.869  mm,	Y =  -23.866  mm,	Z =  356.556  mm,
	W =  171.168 deg,	P =   -3.798 deg,	R =   90.590 deg
};
P[486]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  403.937  mm,	Y =  -26.867  mm,	Z =  356.365  mm,
	W =  171.379 deg,	P =   -3.697 deg,	R =   90.560 deg
};
P[487]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.010  mm,	Y =  -29.871  mm,	Z =  356.181  mm,
	W =  171.541 deg,	P =   -3.544 deg,	R =   90.527 deg
};
P[488]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.081  mm,	Y =  -32.874  mm,	Z =  356.005  mm,
	W =  171.656 deg,	P =   -3.414 deg,	R =   90.500 deg
};
P[489]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.150  mm,	Y =  -35.882  mm,	Z =  355.838  mm,
	W =  171.714 deg,	P =   -3.221 deg,	R =   90.469 deg
};
P[490]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.220  mm,	Y =  -38.888  mm,	Z =  355.679  mm,
	W =  171.722 deg,	P =   -3.059 deg,	R =   90.445 deg
};
P[491]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.288  mm,	Y =  -41.896  mm,	Z =  355.529  mm,
	W =  171.678 deg,	P =   -2.891 deg,	R =   90.423 deg
};
P[492]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.356  mm,	Y =  -44.904  mm,	Z =  355.389  mm,
	W =  171.586 deg,	P =   -2.712 deg,	R =   90.401 deg
};
P[493]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.419  mm,	Y =  -47.910  mm,	Z =  355.257  mm,
	W =  171.441 deg,	P =   -2.588 deg,	R =   90.389 deg
};
P[494]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.492  mm,	Y =  -50.918  mm,	Z =  355.133  mm,
	W =  171.257 deg,	P =   -2.425 deg,	R =   90.373 deg
};
P[495]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.547  mm,	Y =  -53.922  mm,	Z =  355.014  mm,
	W =  171.014 deg,	P =   -2.330 deg,	R =   90.368 deg
};
P[496]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.615  mm,	Y =  -56.923  mm,	Z =  354.902  mm,
	W =  170.737 deg,	P =   -2.268 deg,	R =   90.370 deg
};
P[497]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.675  mm,	Y =  -59.924  mm,	Z =  354.791  mm,
	W =  170.430 deg,	P =   -2.230 deg,	R =   90.376 deg
};
P[498]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.728  mm,	Y =  -62.919  mm,	Z =  354.679  mm,
	W =  170.087 deg,	P =   -2.255 deg,	R =   90.394 deg
};
P[499]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.798  mm,	Y =  -65.913  mm,	Z =  354.569  mm,
	W =  169.730 deg,	P =   -2.301 deg,	R =   90.417 deg
};
P[500]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.837  mm,	Y =  -68.903  mm,	Z =  354.450  mm,
	W =  169.340 deg,	P =   -2.400 deg,	R =   90.452 deg
};
P[501]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.900  mm,	Y =  -71.888  mm,	Z =  354.327  mm,
	W =  168.953 deg,	P =   -2.569 deg,	R =   90.501 deg
};
P[502]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.949  mm,	Y =  -74.870  mm,	Z =  354.193  mm,
	W =  168.546 deg,	P =   -2.779 deg,	R =   90.563 deg
};
P[503]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  404.992  mm,	Y =  -77.846  mm,	Z =  354.044  mm,
	W =  168.142 deg,	P =   -3.045 deg,	R =   90.639 deg
};
P[504]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.056  mm,	Y =  -80.819  mm,	Z =  353.884  mm,
	W =  167.753 deg,	P =   -3.362 deg,	R =   90.729 deg
};
P[505]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.086  mm,	Y =  -83.787  mm,	Z =  353.698  mm,
	W =  167.365 deg,	P =   -3.706 deg,	R =   90.830 deg
};
P[506]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.144  mm,	Y =  -86.749  mm,	Z =  353.498  mm,
	W =  167.004 deg,	P =   -4.140 deg,	R =   90.955 deg
};
P[507]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.188  mm,	Y =  -89.707  mm,	Z =  353.271  mm,
	W =  166.666 deg,	P =   -4.582 deg,	R =   91.085 deg
};
P[508]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.233  mm,	Y =  -92.660  mm,	Z =  353.017  mm,
	W =  166.354 deg,	P =   -5.078 deg,	R =   91.231 deg
};
P[509]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.292  mm,	Y =  -95.607  mm,	Z =  352.740  mm,
	W =  166.078 deg,	P =   -5.614 deg,	R =   91.389 deg
};
P[510]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.333  mm,	Y =  -98.551  mm,	Z =  352.428  mm,
	W =  165.833 deg,	P =   -6.146 deg,	R =   91.548 deg
};
P[511]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.392  mm,	Y = -101.486  mm,	Z =  352.089  mm,
	W =  165.632 deg,	P =   -6.768 deg,	R =   91.729 deg
};
P[512]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.446  mm,	Y = -104.418  mm,	Z =  351.716  mm,
	W =  165.479 deg,	P =   -7.364 deg,	R =   91.901 deg
};
P[513]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.506  mm,	Y = -107.343  mm,	Z =  351.310  mm,
	W =  165.352 deg,	P =   -8.005 deg,	R =   92.085 deg
};
P[514]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.567  mm,	Y = -110.264  mm,	Z =  350.871  mm,
	W =  165.302 deg,	P =   -8.632 deg,	R =   92.254 deg
};
P[515]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.636  mm,	Y = -113.181  mm,	Z =  350.398  mm,
	W =  165.285 deg,	P =   -9.252 deg,	R =   92.418 deg
};
P[516]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.698  mm,	Y = -116.088  mm,	Z =  349.889  mm,
	W =  165.310 deg,	P =   -9.916 deg,	R =   92.585 deg
};
P[517]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  405.771  mm,	Y = -118.992  mm,	Z =  349.349  mm,
	W =  165.389 deg,	P =  -10.552 deg,	R =   92.733 deg
};
P[518]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  407.171  mm,	Y = -121.582  mm,	Z =  349.173  mm,
	W =  165.720 deg,	P =  -11.197 deg,	R =   92.830 deg
};
P[519]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  409.347  mm,	Y = -123.568  mm,	Z =  349.278  mm,
	W =  166.176 deg,	P =  -11.782 deg,	R =   92.876 deg
};
P[520]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  412.232  mm,	Y = -123.510  mm,	Z =  349.972  mm,
	W =  166.657 deg,	P =  -12.001 deg,	R =   92.823 deg
};
P[521]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  415.123  mm,	Y = -123.491  mm,	Z =  350.633  mm,
	W =  167.152 deg,	P =  -12.197 deg,	R =   92.759 deg
};
P[522]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  418.019  mm,	Y = -123.456  mm,	Z =  351.273  mm,
	W =  167.655 deg,	P =  -12.412 deg,	R =   92.693 deg
};
P[523]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.920  mm,	Y = -123.414  mm,	Z =  351.888  mm,
	W =  168.165 deg,	P =  -12.594 deg,	R =   92.616 deg
};
P[524]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.827  mm,	Y = -123.402  mm,	Z =  352.472  mm,
	W =  168.689 deg,	P =  -12.802 deg,	R =   92.538 deg
};
P[525]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  426.738  mm,	Y = -123.341  mm,	Z =  353.040  mm,
	W =  169.189 deg,	P =  -12.989 deg,	R =   92.458 deg
};
P[526]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  429.652  mm,	Y = -123.327  mm,	Z =  353.570  mm,
	W =  169.757 deg,	P =  -13.161 deg,	R =   92.356 deg
};
P[527]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  432.571  mm,	Y = -123.283  mm,	Z =  354.080  mm,
	W =  170.305 deg,	P =  -13.338 deg,	R =   92.257 deg
};
P[528]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  435.495  mm,	Y = -123.245  mm,	Z =  354.560  mm,
	W =  170.860 deg,	P =  -13.489 deg,	R =   92.149 deg
};
P[529]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  438.423  mm,	Y = -123.220  mm,	Z =  355.010  mm,
	W =  171.426 deg,	P =  -13.653 deg,	R =   92.038 deg
};
P[530]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.353  mm,	Y = -123.162  mm,	Z =  355.439  mm,
	W =  171.994 deg,	P =  -13.782 deg,	R =   91.919 deg
};
P[531]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.289  mm,	Y = -123.140  mm,	Z =  355.830  mm,
	W =  172.577 deg,	P =  -13.926 deg,	R =   91.796 deg
};
P[532]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  447.226  mm,	Y = -123.088  mm,	Z =  356.200  mm,
	W =  173.163 deg,	P =  -14.050 deg,	R =   91.667 deg
};
P[533]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  450.168  mm,	Y = -123.048  mm,	Z =  356.537  mm,
	W =  173.755 deg,	P =  -14.154 deg,	R =   91.533 deg
};
P[534]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  453.112  mm,	Y = -123.009  mm,	Z =  356.845  mm,
	W =  174.356 deg,	P =  -14.260 deg,	R =   91.395 deg
};
P[535]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  456.059  mm,	Y = -122.950  mm,	Z =  357.127  mm,
	W =  174.957 deg,	P =  -14.339 deg,	R =   91.252 deg
};
P[536]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.008  mm,	Y = -122.914  mm,	Z =  357.373  mm,
	W =  175.570 deg,	P =  -14.418 deg,	R =   91.105 deg
};
P[537]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.960  mm,	Y = -122.855  mm,	Z =  357.594  mm,
	W =  176.175 deg,	P =  -14.481 deg,	R =   90.958 deg
};
P[538]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.912  mm,	Y = -122.806  mm,	Z =  357.782  mm,
	W =  176.801 deg,	P =  -14.525 deg,	R =   90.803 deg
};
P[539]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.867  mm,	Y = -122.752  mm,	Z =  357.941  mm,
	W =  177.426 deg,	P =  -14.562 deg,	R =   90.647 deg
};
P[540]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.823  mm,	Y = -122.691  mm,	Z =  358.069  mm,
	W =  178.047 deg,	P =  -14.580 deg,	R =   90.492 deg
};
P[541]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.779  mm,	Y = -122.631  mm,	Z =  358.167  mm,
	W =  178.677 deg,	P =  -14.586 deg,	R =   90.333 deg
};
P[542]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.737  mm,	Y = -122.570  mm,	Z =  358.233  mm,
	W =  179.303 deg,	P =  -14.582 deg,	R =   90.175 deg
};
P[543]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.695  mm,	Y = -122.508  mm,	Z =  358.268  mm,
	W =  179.934 deg,	P =  -14.560 deg,	R =   90.017 deg
};
P[544]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.652  mm,	Y = -122.442  mm,	Z =  358.273  mm,
	W = -179.431 deg,	P =  -14.527 deg,	R =   89.857 deg
};
P[545]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.611  mm,	Y = -122.375  mm,	Z =  358.246  mm,
	W = -178.808 deg,	P =  -14.481 deg,	R =   89.702 deg
};
P[546]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.568  mm,	Y = -122.307  mm,	Z =  358.188  mm,
	W = -178.174 deg,	P =  -14.421 deg,	R =   89.545 deg
};
P[547]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  491.524  mm,	Y = -122.234  mm,	Z =  358.100  mm,
	W = -177.547 deg,	P =  -14.345 deg,	R =   89.392 deg
};
P[548]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  494.480  mm,	Y = -122.158  mm,	Z =  357.981  mm,
	W = -176.924 deg,	P =  -14.261 deg,	R =   89.242 deg
};
P[549]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  497.434  mm,	Y = -122.086  mm,	Z =  357.830  mm,
	W = -176.294 deg,	P =  -14.167 deg,	R =   89.092 deg
};
P[550]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.387  mm,	Y = -121.997  mm,	Z =  357.652  mm,
	W = -175.685 deg,	P =  -14.054 deg,	R =   88.950 deg
};
P[551]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  503.337  mm,	Y = -121.924  mm,	Z =  357.438  mm,
	W = -175.063 deg,	P =  -13.938 deg,	R =   88.808 deg
};
P[552]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.285  mm,	Y = -121.837  mm,	Z =  357.198  mm,
	W = -174.453 deg,	P =  -13.801 deg,	R =   88.673 deg
};
P[553]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.231  mm,	Y = -121.747  mm,	Z =  356.927  mm,
	W = -173.850 deg,	P =  -13.664 deg,	R =   88.542 deg
};
P[554]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  512.174  mm,	Y = -121.669  mm,	Z =  356.623  mm,
	W = -173.245 deg,	P =  -13.519 deg,	R =   88.414 deg
};
P[555]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  515.114  mm,	Y = -121.560  mm,	Z =  356.295  mm,
	W = -172.658 deg,	P =  -13.353 deg,	R =   88.296 deg
};
P[556]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  518.051  mm,	Y = -121.483  mm,	Z =  355.931  mm,
	W = -172.063 deg,	P =  -13.199 deg,	R =   88.177 deg
};
P[557]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  520.985  mm,	Y = -121.382  mm,	Z =  355.542  mm,
	W = -171.487 deg,	P =  -13.015 deg,	R =   88.069 deg
};
P[558]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  523.914  mm,	Y = -121.281  mm,	Z =  355.124  mm,
	W = -170.911 deg,	P =  -12.842 deg,	R =   87.964 deg
};
P[559]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.840  mm,	Y = -121.197  mm,	Z =  354.673  mm,
	W = -170.346 deg,	P =  -12.661 deg,	R =   87.865 deg
};
P[560]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.762  mm,	Y = -121.072  mm,	Z =  354.202  mm,
	W = -169.789 deg,	P =  -12.462 deg,	R =   87.774 deg
};
P[561]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  532.679  mm,	Y = -120.996  mm,	Z =  353.693  mm,
	W = -169.237 deg,	P =  -12.285 deg,	R =   87.684 deg
};
P[562]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  535.593  mm,	Y = -120.879  mm,	Z =  353.164  mm,
	W = -168.701 deg,	P =  -12.078 deg,	R =   87.606 deg
};
P[563]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  538.500  mm,	Y = -120.777  mm,	Z =  352.605  mm,
	W = -168.159 deg,	P =  -11.889 deg,	R =   87.527 deg
};
P[564]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  541.405  mm,	Y = -120.684  mm,	Z =  352.016  mm,
	W = -167.645 deg,	P =  -11.690 deg,	R =   87.459 deg
};
P[565]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.303  mm,	Y = -120.554  mm,	Z =  351.409  mm,
	W = -167.121 deg,	P =  -11.480 deg,	R =   87.395 deg
};
P[566]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.197  mm,	Y = -120.480  mm,	Z =  350.764  mm,
	W = -166.625 deg,	P =  -11.295 deg,	R =   87.334 deg
};
P[567]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.541  mm,	Y = -118.698  mm,	Z =  350.574  mm,
	W = -166.165 deg,	P =  -10.738 deg,	R =   87.373 deg
};
P[568]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.684  mm,	Y = -115.802  mm,	Z =  351.102  mm,
	W = -166.082 deg,	P =  -10.002 deg,	R =   87.536 deg
};
P[569]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.826  mm,	Y = -112.897  mm,	Z =  351.591  mm,
	W = -166.053 deg,	P =   -9.297 deg,	R =   87.702 deg
};
P[570]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.974  mm,	Y = -109.986  mm,	Z =  352.040  mm,
	W = -166.063 deg,	P =   -8.581 deg,	R =   87.879 deg
};
P[571]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.125  mm,	Y = -107.071  mm,	Z =  352.450  mm,
	W = -166.116 deg,	P =   -7.863 deg,	R =   88.063 deg
};
P[572]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.277  mm,	Y = -104.146  mm,	Z =  352.822  mm,
	W = -166.213 deg,	P =   -7.192 deg,	R =   88.240 deg
};
P[573]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.381  mm,	Y = -101.220  mm,	Z =  353.169  mm,
	W = -166.359 deg,	P =   -6.487 deg,	R =   88.429 deg
};
P[574]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.281  mm,	Y =  -98.291  mm,	Z =  353.527  mm,
	W = -166.587 deg,	P =   -5.837 deg,	R =   88.611 deg
};
P[575]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.187  mm,	Y =  -95.356  mm,	Z =  353.849  mm,
	W = -166.851 deg,	P =   -5.210 deg,	R =   88.785 deg
};
P[576]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  550.061  mm,	Y =  -92.419  mm,	Z =  354.143  mm,
	W = -167.151 deg,	P =   -4.605 deg,	R =   88.951 deg
};
P[577]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.978  mm,	Y =  -89.471  mm,	Z =  354.396  mm,
	W = -167.477 deg,	P =   -4.060 deg,	R =   89.099 deg
};
P[578]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.844  mm,	Y =  -86.523  mm,	Z =  354.630  mm,
	W = -167.833 deg,	P =   -3.532 deg,	R =   89.239 deg
};
P[579]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.738  mm,	Y =  -83.568  mm,	Z =  354.830  mm,
	W = -168.213 deg,	P =   -3.053 deg,	R =   89.363 deg
};
P[580]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.632  mm,	Y =  -80.604  mm,	Z =  355.006  mm,
	W = -168.601 deg,	P =   -2.661 deg,	R =   89.464 deg
};
P[581]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.496  mm,	Y =  -77.639  mm,	Z =  355.166  mm,
	W = -169.015 deg,	P =   -2.302 deg,	R =   89.553 deg
};
P[582]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.416  mm,	Y =  -74.664  mm,	Z =  355.297  mm,
	W = -169.416 deg,	P =   -2.020 deg,	R =   89.623 deg
};
P[583]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.276  mm,	Y =  -71.688  mm,	Z =  355.425  mm,
	W = -169.834 deg,	P =   -1.798 deg,	R =   89.678 deg
};
P[584]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.177  mm,	Y =  -68.706  mm,	Z =  355.534  mm,
	W = -170.238 deg,	P =   -1.623 deg,	R =   89.721 deg
};
P[585]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  549.072  mm,	Y =  -65.716  mm,	Z =  355.637  mm,
	W = -170.626 deg,	P =   -1.549 deg,	R =   89.744 deg
};
P[586]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.949  mm,	Y =  -62.725  mm,	Z =  355.738  mm,
	W = -170.999 deg,	P =   -1.504 deg,	R =   89.762 deg
};
P[587]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.872  mm,	Y =  -59.725  mm,	Z =  355.832  mm,
	W = -171.349 deg,	P =   -1.545 deg,	R =   89.765 deg
};
P[588]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.748  mm,	Y =  -56.724  mm,	Z =  355.934  mm,
	W = -171.660 deg,	P =   -1.632 deg,	R =   89.761 deg
};
P[589]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.659  mm,	Y =  -53.719  mm,	Z =  356.038  mm,
	W = -171.942 deg,	P =   -1.762 deg,	R =   89.751 deg
};
P[590]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.563  mm,	Y =  -50.709  mm,	Z =  356.151  mm,
	W = -172.188 deg,	P =   -1.962 deg,	R =   89.731 deg
};
P[591]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.464  mm,	Y =  -47.698  mm,	Z =  356.275  mm,
	W = -172.413 deg,	P =   -2.189 deg,	R =   89.709 deg
};
P[592]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.380  mm,	Y =  -44.685  mm,	Z =  356.410  mm,
	W = -172.535 deg,	P =   -2.446 deg,	R =   89.680 deg
};
P[593]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.284  mm,	Y =  -41.670  mm,	Z =  356.561  mm,
	W = -172.656 deg,	P =   -2.737 deg,	R =   89.647 deg
};
P[594]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.200  mm,	Y =  -38.656  mm,	Z =  356.726  mm,
	W = -172.697 deg,	P =   -3.023 deg,	R =   89.613 deg
};
P[595]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.113  mm,	Y =  -35.640  mm,	Z =  356.907  mm,
	W = -172.708 deg,	P =   -3.339 deg,	R =   89.573 deg
};
P[596]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  548.034  mm,	Y =  -32.628  mm,	Z =  357.104  mm,
	W = -172.662 deg,	P =   -3.624 deg,	R =   89.534 deg
};
P[597]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.946  mm,	Y =  -29.615  mm,	Z =  357.318  mm,
	W = -172.567 deg,	P =   -3.925 deg,	R =   89.488 deg
};
P[598]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.877  mm,	Y =  -26.604  mm,	Z =  357.544  mm,
	W = -172.440 deg,	P =   -4.207 deg,	R =   89.442 deg
};
P[599]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.797  mm,	Y =  -23.599  mm,	Z =  357.786  mm,
	W = -172.243 deg,	P =   -4.428 deg,	R =   89.397 deg
};
P[600]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.722  mm,	Y =  -20.595  mm,	Z =  358.039  mm,
	W = -172.022 deg,	P =   -4.636 deg,	R =   89.351 deg
};
P[601]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.665  mm,	Y =  -17.595  mm,	Z =  358.300  mm,
	W = -171.759 deg,	P =   -4.786 deg,	R =   89.308 deg
};
P[602]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.574  mm,	Y =  -14.601  mm,	Z =  358.572  mm,
	W = -171.463 deg,	P =   -4.887 deg,	R =   89.267 deg
};
P[603]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.533  mm,	Y =  -11.608  mm,	Z =  358.842  mm,
	W = -171.143 deg,	P =   -4.946 deg,	R =   89.230 deg
};
P[604]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.461  mm,	Y =   -8.623  mm,	Z =  359.118  mm,
	W = -170.795 deg,	P =   -4.913 deg,	R =   89.205 deg
};
P[605]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.401  mm,	Y =   -5.641  mm,	Z =  359.390  mm,
	W = -170.434 deg,	P =   -4.834 deg,	R =   89.186 deg
};
P[606]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.362  mm,	Y =   -2.662  mm,	Z =  359.652  mm,
	W = -170.063 deg,	P =   -4.688 deg,	R =   89.180 deg
};
P[607]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.277  mm,	Y =    0.311  mm,	Z =  359.913  mm,
	W = -169.689 deg,	P =   -4.459 deg,	R =   89.190 deg
};
P[608]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.256  mm,	Y =    3.284  mm,	Z =  360.150  mm,
	W = -169.315 deg,	P =   -4.198 deg,	R =   89.209 deg
};
P[609]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.189  mm,	Y =    6.248  mm,	Z =  360.377  mm,
	W = -168.949 deg,	P =   -3.813 deg,	R =   89.256 deg
};
P[610]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.137  mm,	Y =    9.211  mm,	Z =  360.583  mm,
	W = -168.587 deg,	P =   -3.386 deg,	R =   89.317 deg
};
P[611]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.084  mm,	Y =   12.172  mm,	Z =  360.764  mm,
	W = -168.264 deg,	P =   -2.915 deg,	R =   89.395 deg
};
P[612]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  547.019  mm,	Y =   15.128  mm,	Z =  360.920  mm,
	W = -167.952 deg,	P =   -2.352 deg,	R =   89.498 deg
};
P[613]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.979  mm,	Y =   18.086  mm,	Z =  361.040  mm,
	W = -167.673 deg,	P =   -1.793 deg,	R =   89.608 deg
};
P[614]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.918  mm,	Y =   21.035  mm,	Z =  361.132  mm,
	W = -167.425 deg,	P =   -1.106 deg,	R =   89.753 deg
};
P[615]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.861  mm,	Y =   23.986  mm,	Z =  361.187  mm,
	W = -167.217 deg,	P =   -0.427 deg,	R =   89.903 deg
};
P[616]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.803  mm,	Y =   26.933  mm,	Z =  361.203  mm,
	W = -167.041 deg,	P =    0.303 deg,	R =   90.070 deg
};
P[617]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.730  mm,	Y =   29.877  mm,	Z =  361.183  mm,
	W = -166.904 deg,	P =    1.082 deg,	R =   90.252 deg
};
P[618]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.663  mm,	Y =   32.822  mm,	Z =  361.120  mm,
	W = -166.821 deg,	P =    1.827 deg,	R =   90.428 deg
};
P[619]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.585  mm,	Y =   35.760  mm,	Z =  361.016  mm,
	W = -166.781 deg,	P =    2.646 deg,	R =   90.621 deg
};
P[620]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.503  mm,	Y =   38.699  mm,	Z =  360.871  mm,
	W = -166.785 deg,	P =    3.436 deg,	R =   90.806 deg
};
P[621]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.422  mm,	Y =   41.635  mm,	Z =  360.682  mm,
	W = -166.835 deg,	P =    4.233 deg,	R =   90.989 deg
};
P[622]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.327  mm,	Y =   44.567  mm,	Z =  360.454  mm,
	W = -166.926 deg,	P =    5.034 deg,	R =   91.167 deg
};
P[623]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.238  mm,	Y =   47.499  mm,	Z =  360.182  mm,
	W = -167.064 deg,	P =    5.784 deg,	R =   91.326 deg
};
P[624]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.137  mm,	Y =   50.427  mm,	Z =  359.872  mm,
	W = -167.243 deg,	P =    6.546 deg,	R =   91.479 deg
};
P[625]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  546.027  mm,	Y =   53.354  mm,	Z =  359.525  mm,
	W = -167.463 deg,	P =    7.260 deg,	R =   91.610 deg
};
P[626]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.935  mm,	Y =   56.279  mm,	Z =  359.136  mm,
	W = -167.718 deg,	P =    7.923 deg,	R =   91.719 deg
};
P[627]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.797  mm,	Y =   59.202  mm,	Z =  358.722  mm,
	W = -168.008 deg,	P =    8.562 deg,	R =   91.811 deg
};
P[628]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.706  mm,	Y =   62.126  mm,	Z =  358.266  mm,
	W = -168.325 deg,	P =    9.125 deg,	R =   91.877 deg
};
P[629]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.580  mm,	Y =   65.047  mm,	Z =  357.788  mm,
	W = -168.664 deg,	P =    9.652 deg,	R =   91.925 deg
};
P[630]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.456  mm,	Y =   67.968  mm,	Z =  357.284  mm,
	W = -169.031 deg,	P =   10.131 deg,	R =   91.952 deg
};
P[631]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.356  mm,	Y =   70.893  mm,	Z =  356.751  mm,
	W = -169.400 deg,	P =   10.498 deg,	R =   91.953 deg
};
P[632]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.207  mm,	Y =   73.815  mm,	Z =  356.209  mm,
	W = -169.796 deg,	P =   10.836 deg,	R =   91.938 deg
};
P[633]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  545.123  mm,	Y =   76.743  mm,	Z =  355.639  mm,
	W = -170.181 deg,	P =   11.074 deg,	R =   91.904 deg
};
P[634]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.993  mm,	Y =   79.672  mm,	Z =  355.066  mm,
	W = -170.568 deg,	P =   11.261 deg,	R =   91.858 deg
};
P[635]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.888  mm,	Y =   82.604  mm,	Z =  354.480  mm,
	W = -170.947 deg,	P =   11.387 deg,	R =   91.802 deg
};
P[636]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.781  mm,	Y =   85.542  mm,	Z =  353.889  mm,
	W = -171.310 deg,	P =   11.410 deg,	R =   91.732 deg
};
P[637]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.655  mm,	Y =   88.482  mm,	Z =  353.301  mm,
	W = -171.657 deg,	P =   11.411 deg,	R =   91.662 deg
};
P[638]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.574  mm,	Y =   91.430  mm,	Z =  352.709  mm,
	W = -171.976 deg,	P =   11.298 deg,	R =   91.582 deg
};
P[639]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.448  mm,	Y =   94.381  mm,	Z =  352.128  mm,
	W = -172.262 deg,	P =   11.163 deg,	R =   91.507 deg
};
P[640]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  544.361  mm,	Y =   97.338  mm,	Z =  351.551  mm,
	W = -172.530 deg,	P =   10.956 deg,	R =   91.428 deg
};
P[641]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  543.045  mm,	Y =  100.011  mm,	Z =  351.194  mm,
	W = -172.879 deg,	P =   10.808 deg,	R =   91.342 deg
};
P[642]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  540.819  mm,	Y =  101.997  mm,	Z =  351.076  mm,
	W = -173.256 deg,	P =   10.730 deg,	R =   91.261 deg
};
P[643]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  538.591  mm,	Y =  103.984  mm,	Z =  350.948  mm,
	W = -173.626 deg,	P =   10.589 deg,	R =   91.176 deg
};
P[644]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  536.362  mm,	Y =  105.978  mm,	Z =  350.813  mm,
	W = -173.967 deg,	P =   10.373 deg,	R =   91.090 deg
};
P[645]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  534.131  mm,	Y =  107.972  mm,	Z =  350.674  mm,
	W = -174.281 deg,	P =   10.154 deg,	R =   91.011 deg
};
P[646]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  531.898  mm,	Y =  109.973  mm,	Z =  350.532  mm,
	W = -174.573 deg,	P =    9.823 deg,	R =   90.929 deg
};
P[647]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.664  mm,	Y =  111.975  mm,	Z =  350.393  mm,
	W = -174.855 deg,	P =    9.468 deg,	R =   90.849 deg
};
P[648]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.801  mm,	Y =  112.801  mm,	Z =  350.501  mm,
	W = -175.168 deg,	P =    9.326 deg,	R =   90.785 deg
};
P[649]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  523.837  mm,	Y =  112.699  mm,	Z =  350.757  mm,
	W = -175.519 deg,	P =    9.337 deg,	R =   90.728 deg
};
P[650]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  520.869  mm,	Y =  112.600  mm,	Z =  350.995  mm,
	W = -175.827 deg,	P =    9.364 deg,	R =   90.680 deg
};
P[651]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  517.901  mm,	Y =  112.500  mm,	Z =  351.217  mm,
	W = -176.150 deg,	P =    9.385 deg,	R =   90.629 deg
};
P[652]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  514.931  mm,	Y =  112.406  mm,	Z =  351.421  mm,
	W = -176.469 deg,	P =    9.408 deg,	R =   90.578 deg
};
P[653]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.960  mm,	Y =  112.309  mm,	Z =  351.610  mm,
	W = -176.782 deg,	P =    9.432 deg,	R =   90.528 deg
};
P[654]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.988  mm,	Y =  112.215  mm,	Z =  351.782  mm,
	W = -177.104 deg,	P =    9.452 deg,	R =   90.476 deg
};
P[655]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.014  mm,	Y =  112.118  mm,	Z =  351.939  mm,
	W = -177.401 deg,	P =    9.485 deg,	R =   90.429 deg
};
P[656]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  503.040  mm,	Y =  112.024  mm,	Z =  352.080  mm,
	W = -177.715 deg,	P =    9.513 deg,	R =   90.378 deg
};
P[657]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.064  mm,	Y =  111.931  mm,	Z =  352.206  mm,
	W = -178.008 deg,	P =    9.540 deg,	R =   90.330 deg
};
P[658]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  497.088  mm,	Y =  111.838  mm,	Z =  352.315  mm,
	W = -178.306 deg,	P =    9.570 deg,	R =   90.282 deg
};
P[659]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  494.111  mm,	Y =  111.748  mm,	Z =  352.410  mm,
	W = -178.610 deg,	P =    9.595 deg,	R =   90.232 deg
};
P[660]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  491.133  mm,	Y =  111.656  mm,	Z =  352.489  mm,
	W = -178.901 deg,	P =    9.628 deg,	R =   90.184 deg
};
P[661]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.156  mm,	Y =  111.566  mm,	Z =  352.553  mm,
	W = -179.201 deg,	P =    9.656 deg,	R =   90.134 deg
};
P[662]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.177  mm,	Y =  111.478  mm,	Z =  352.602  mm,
	W = -179.490 deg,	P =    9.684 deg,	R =   90.086 deg
};
P[663]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.198  mm,	Y =  111.389  mm,	Z =  352.635  mm,
	W = -179.781 deg,	P =    9.712 deg,	R =   90.037 deg
};
P[664]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.220  mm,	Y =  111.302  mm,	Z =  352.654  mm,
	W =  179.921 deg,	P =    9.737 deg,	R =   89.987 deg
};
P[665]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.241  mm,	Y =  111.215  mm,	Z =  352.658  mm,
	W =  179.632 deg,	P =    9.764 deg,	R =   89.938 deg
};
P[666]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.262  mm,	Y =  111.128  mm,	Z =  352.646  mm,
	W =  179.334 deg,	P =    9.787 deg,	R =   89.887 deg
};
P[667]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.283  mm,	Y =  111.043  mm,	Z =  352.619  mm,
	W =  179.044 deg,	P =    9.812 deg,	R =   89.837 deg
};
P[668]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.305  mm,	Y =  110.959  mm,	Z =  352.577  mm,
	W =  178.744 deg,	P =    9.829 deg,	R =   89.785 deg
};
P[669]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.326  mm,	Y =  110.875  mm,	Z =  352.520  mm,
	W =  178.447 deg,	P =    9.849 deg,	R =   89.734 deg
};
P[670]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.348  mm,	Y =  110.793  mm,	Z =  352.447  mm,
	W =  178.154 deg,	P =    9.865 deg,	R =   89.684 deg
};
P[671]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  458.372  mm,	Y =  110.712  mm,	Z =  352.359  mm,
	W =  177.845 deg,	P =    9.877 deg,	R =   89.630 deg
};
P[672]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  455.395  mm,	Y =  110.632  mm,	Z =  352.255  mm,
	W =  177.548 deg,	P =    9.894 deg,	R =   89.578 deg
};
P[673]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  452.419  mm,	Y =  110.553  mm,	Z =  352.135  mm,
	W =  177.234 deg,	P =    9.894 deg,	R =   89.524 deg
};
P[674]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  449.444  mm,	Y =  110.476  mm,	Z =  351.999  mm,
	W =  176.924 deg,	P =    9.900 deg,	R =   89.471 deg
};
P[675]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  446.470  mm,	Y =  110.400  mm,	Z =  351.847  mm,
	W =  176.621 deg,	P =    9.902 deg,	R =   89.418 deg
};
P[676]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.498  mm,	Y =  110.327  mm,	Z =  351.678  mm,
	W =  176.291 deg,	P =    9.898 deg,	R =   89.362 deg
};
P[677]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.525  mm,	Y =  110.254  mm,	Z =  351.493  mm,
	W =  175.981 deg,	P =    9.901 deg,	R =   89.308 deg
};
P[678]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  437.556  mm,	Y =  110.184  mm,	Z =  351.291  mm,
	W =  175.643 deg,	P =    9.881 deg,	R =   89.251 deg
};
P[679]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  434.587  mm,	Y =  110.115  mm,	Z =  351.072  mm,
	W =  175.312 deg,	P =    9.869 deg,	R =   89.195 deg
};
P[680]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  431.619  mm,	Y =  110.048  mm,	Z =  350.836  mm,
	W =  174.995 deg,	P =    9.851 deg,	R =   89.142 deg
};
P[681]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  428.776  mm,	Y =  109.160  mm,	Z =  350.738  mm,
	W =  174.641 deg,	P =    9.970 deg,	R =   89.070 deg
};
P[682]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  426.904  mm,	Y =  106.816  mm,	Z =  350.986  mm,
	W =  174.380 deg,	P =   10.353 deg,	R =   88.987 deg
};
P[683]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.032  mm,	Y =  104.479  mm,	Z =  351.238  mm,
	W =  174.079 deg,	P =   10.653 deg,	R =   88.902 deg
};
P[684]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.163  mm,	Y =  102.144  mm,	Z =  351.492  mm,
	W =  173.754 deg,	P =   10.922 deg,	R =   88.812 deg
};
P[685]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.295  mm,	Y =   99.814  mm,	Z =  351.745  mm,
	W =  173.411 deg,	P =   11.103 deg,	R =   88.726 deg
};
P[686]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.217  mm,	Y =   97.040  mm,	Z =  352.178  mm,
	W =  173.076 deg,	P =   11.330 deg,	R =   88.633 deg
};
P[687]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.276  mm,	Y =   94.085  mm,	Z =  352.794  mm,
	W =  172.850 deg,	P =   11.581 deg,	R =   88.557 deg
};
P[688]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.347  mm,	Y =   91.136  mm,	Z =  353.423  mm,
	W =  172.596 deg,	P =   11.797 deg,	R =   88.478 deg
};
P[689]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.387  mm,	Y =   88.193  mm,	Z =  354.057  mm,
	W =  172.307 deg,	P =   11.936 deg,	R =   88.400 deg
};
P[690]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.453  mm,	Y =   85.256  mm,	Z =  354.702  mm,
	W =  172.005 deg,	P =   12.015 deg,	R =   88.325 deg
};
P[691]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.493  mm,	Y =   82.323  mm,	Z =  355.345  mm,
	W =  171.672 deg,	P =   12.028 deg,	R =   88.253 deg
};
P[692]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.538  mm,	Y =   79.397  mm,	Z =  355.986  mm,
	W =  171.341 deg,	P =   11.945 deg,	R =   88.195 deg
};
P[693]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.589  mm,	Y =   76.475  mm,	Z =  356.623  mm,
	W =  170.992 deg,	P =   11.791 deg,	R =   88.144 deg
};
P[694]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.612  mm,	Y =   73.556  mm,	Z =  357.246  mm,
	W =  170.643 deg,	P =   11.563 deg,	R =   88.108 deg
};
P[695]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.671  mm,	Y =   70.641  mm,	Z =  357.860  mm,
	W =  170.306 deg,	P =   11.239 deg,	R =   88.093 deg
};
P[696]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.693  mm,	Y =   67.725  mm,	Z =  358.451  mm,
	W =  169.969 deg,	P =   10.872 deg,	R =   88.089 deg
};
P[697]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.738  mm,	Y =   64.814  mm,	Z =  359.022  mm,
	W =  169.655 deg,	P =   10.374 deg,	R =   88.117 deg
};
P[698]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.779  mm,	Y =   61.901  mm,	Z =  359.567  mm,
	W =  169.360 deg,	P =    9.842 deg,	R =   88.161 deg
};
P[699]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.810  mm,	Y =   58.989  mm,	Z =  360.079  mm,
	W =  169.079 deg,	P =    9.218 deg,	R =   88.230 deg
};
P[700]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.870  mm,	Y =   56.076  mm,	Z =  360.564  mm,
	W =  168.847 deg,	P =    8.540 deg,	R =   88.323 deg
};
P[701]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.905  mm,	Y =   53.159  mm,	Z =  361.006  mm,
	W =  168.631 deg,	P =    7.833 deg,	R =   88.430 deg
};
P[702]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  420.964  mm,	Y =   50.246  mm,	Z =  361.413  mm,
	W =  168.456 deg,	P =    7.007 deg,	R =   88.573 deg
};
P[703]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.024  mm,	Y =   47.327  mm,	Z =  361.777  mm,
	W =  168.321 deg,	P =    6.184 deg,	R =   88.724 deg
};
P[704]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.085  mm,	Y =   44.408  mm,	Z =  362.096  mm,
	W =  168.212 deg,	P =    5.300 deg,	R =   88.896 deg
};
P[705]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.162  mm,	Y =   41.485  mm,	Z =  362.372  mm,
	W =  168.168 deg,	P =    4.405 deg,	R =   89.078 deg
};
P[706]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.242  mm,	Y =   38.560  mm,	Z =  362.599  mm,
	W =  168.129 deg,	P =    3.484 deg,	R =   89.268 deg
};
P[707]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.326  mm,	Y =   35.633  mm,	Z =  362.779  mm,
	W =  168.179 deg,	P =    2.559 deg,	R =   89.465 deg
};
P[708]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.420  mm,	Y =   32.704  mm,	Z =  362.910  mm,
	W =  168.250 deg,	P =    1.629 deg,	R =   89.661 deg
};
P[709]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.516  mm,	Y =   29.772  mm,	Z =  362.993  mm,
	W =  168.353 deg,	P =    0.723 deg,	R =   89.851 deg
};
P[710]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.621  mm,	Y =   26.838  mm,	Z =  363.029  mm,
	W =  168.515 deg,	P =   -0.173 deg,	R =   90.035 deg
};
P[711]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.735  mm,	Y =   23.902  mm,	Z =  363.020  mm,
	W =  168.685 deg,	P =   -1.029 deg,	R =   90.206 deg
};
P[712]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.849  mm,	Y =   20.963  mm,	Z =  362.965  mm,
	W =  168.932 deg,	P =   -1.845 deg,	R =   90.361 deg
};
P[713]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  421.973  mm,	Y =   18.023  mm,	Z =  362.870  mm,
	W =  169.187 deg,	P =   -2.625 deg,	R =   90.501 deg
};
P[714]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.095  mm,	Y =   15.078  mm,	Z =  362.734  mm,
	W =  169.480 deg,	P =   -3.319 deg,	R =   90.616 deg
};
P[715]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.221  mm,	Y =   12.133  mm,	Z =  362.563  mm,
	W =  169.788 deg,	P =   -3.977 deg,	R =   90.716 deg
};
P[716]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.335  mm,	Y =    9.182  mm,	Z =  362.357  mm,
	W =  170.121 deg,	P =   -4.530 deg,	R =   90.788 deg
};
P[717]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.461  mm,	Y =    6.229  mm,	Z =  362.123  mm,
	W =  170.470 deg,	P =   -5.018 deg,	R =   90.841 deg
};
P[718]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.597  mm,	Y =    3.273  mm,	Z =  361.868  mm,
	W =  170.827 deg,	P =   -5.438 deg,	R =   90.877 deg
};
P[719]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.703  mm,	Y =    0.310  mm,	Z =  361.587  mm,
	W =  171.193 deg,	P =   -5.733 deg,	R =   90.887 deg
};
P[720]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.860  mm,	Y =   -2.653  mm,	Z =  361.299  mm,
	W =  171.556 deg,	P =   -6.000 deg,	R =   90.889 deg
};
P[721]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  422.971  mm,	Y =   -5.627  mm,	Z =  360.993  mm,
	W =  171.919 deg,	P =   -6.108 deg,	R =   90.865 deg
};
P[722]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.101  mm,	Y =   -8.603  mm,	Z =  360.683  mm,
	W =  172.263 deg,	P =   -6.170 deg,	R =   90.837 deg
};
P[723]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.228  mm,	Y =  -11.586  mm,	Z =  360.373  mm,
	W =  172.605 deg,	P =   -6.140 deg,	R =   90.795 deg
};
P[724]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.333  mm,	Y =  -14.578  mm,	Z =  360.062  mm,
	W =  172.920 deg,	P =   -5.997 deg,	R =   90.743 deg
};
P[725]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.465  mm,	Y =  -17.571  mm,	Z =  359.763  mm,
	W =  173.207 deg,	P =   -5.845 deg,	R =   90.695 deg
};
P[726]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.563  mm,	Y =  -20.576  mm,	Z =  359.471  mm,
	W =  173.461 deg,	P =   -5.541 deg,	R =   90.634 deg
};
P[727]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.675  mm,	Y =  -23.583  mm,	Z =  359.196  mm,
	W =  173.683 deg,	P =   -5.223 deg,	R =   90.577 deg
};
P[728]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.777  mm,	Y =  -26.597  mm,	Z =  358.939  mm,
	W =  173.869 deg,	P =   -4.840 deg,	R =   90.519 deg
};
P[729]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.872  mm,	Y =  -29.618  mm,	Z =  358.702  mm,
	W =  174.014 deg,	P =   -4.392 deg,	R =   90.460 deg
};
P[730]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  423.971  mm,	Y =  -32.639  mm,	Z =  358.489  mm,
	W =  174.120 deg,	P =   -3.962 deg,	R =   90.408 deg
};
P[731]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.058  mm,	Y =  -35.668  mm,	Z =  358.300  mm,
	W =  174.177 deg,	P =   -3.439 deg,	R =   90.350 deg
};
P[732]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.145  mm,	Y =  -38.697  mm,	Z =  358.138  mm,
	W =  174.191 deg,	P =   -2.952 deg,	R =   90.300 deg
};
P[733]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.226  mm,	Y =  -41.727  mm,	Z =  358.002  mm,
	W =  174.160 deg,	P =   -2.461 deg,	R =   90.252 deg
};
P[734]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.308  mm,	Y =  -44.759  mm,	Z =  357.892  mm,
	W =  174.089 deg,	P =   -1.969 deg,	R =   90.204 deg
};
P[735]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.375  mm,	Y =  -47.787  mm,	Z =  357.805  mm,
	W =  173.971 deg,	P =   -1.535 deg,	R =   90.162 deg
};
P[736]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.452  mm,	Y =  -50.817  mm,	Z =  357.744  mm,
	W =  173.822 deg,	P =   -1.097 deg,	R =   90.119 deg
};
P[737]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.511  mm,	Y =  -53.842  mm,	Z =  357.701  mm,
	W =  173.622 deg,	P =   -0.730 deg,	R =   90.082 deg
};
P[738]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.573  mm,	Y =  -56.862  mm,	Z =  357.677  mm,
	W =  173.394 deg,	P =   -0.439 deg,	R =   90.051 deg
};
P[739]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.633  mm,	Y =  -59.879  mm,	Z =  357.668  mm,
	W =  173.138 deg,	P =   -0.195 deg,	R =   90.023 deg
};
P[740]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.671  mm,	Y =  -62.889  mm,	Z =  357.667  mm,
	W =  172.851 deg,	P =   -0.044 deg,	R =   90.005 deg
};
P[741]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.735  mm,	Y =  -65.894  mm,	Z =  357.675  mm,
	W =  172.554 deg,	P =    0.034 deg,	R =   89.996 deg
};
P[742]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.764  mm,	Y =  -68.895  mm,	Z =  357.681  mm,
	W =  172.226 deg,	P =    0.043 deg,	R =   89.994 deg
};
P[743]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.807  mm,	Y =  -71.885  mm,	Z =  357.686  mm,
	W =  171.897 deg,	P =   -0.093 deg,	R =   90.013 deg
};
P[744]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.848  mm,	Y =  -74.872  mm,	Z =  357.683  mm,
	W =  171.560 deg,	P =   -0.280 deg,	R =   90.041 deg
};
P[745]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.865  mm,	Y =  -77.851  mm,	Z =  357.663  mm,
	W =  171.220 deg,	P =   -0.578 deg,	R =   90.089 deg
};
P[746]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.917  mm,	Y =  -80.823  mm,	Z =  357.631  mm,
	W =  170.893 deg,	P =   -0.972 deg,	R =   90.156 deg
};
P[747]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.933  mm,	Y =  -83.790  mm,	Z =  357.570  mm,
	W =  170.564 deg,	P =   -1.416 deg,	R =   90.235 deg
};
P[748]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  424.969  mm,	Y =  -86.746  mm,	Z =  357.485  mm,
	W =  170.261 deg,	P =   -2.017 deg,	R =   90.346 deg
};
P[749]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.007  mm,	Y =  -89.700  mm,	Z =  357.369  mm,
	W =  169.975 deg,	P =   -2.640 deg,	R =   90.467 deg
};
P[750]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.027  mm,	Y =  -92.644  mm,	Z =  357.213  mm,
	W =  169.709 deg,	P =   -3.360 deg,	R =   90.610 deg
};
P[751]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.083  mm,	Y =  -95.581  mm,	Z =  357.025  mm,
	W =  169.476 deg,	P =   -4.148 deg,	R =   90.770 deg
};
P[752]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  425.119  mm,	Y =  -98.515  mm,	Z =  356.789  mm,
	W =  169.267 deg,	P =   -4.950 deg,	R =   90.937 deg
};
P[753]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  426.015  mm,	Y = -101.316  mm,	Z =  356.686  mm,
	W =  169.254 deg,	P =   -5.791 deg,	R =   91.097 deg
};
P[754]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  427.704  mm,	Y = -103.736  mm,	Z =  356.732  mm,
	W =  169.446 deg,	P =   -6.484 deg,	R =   91.205 deg
};
P[755]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  430.545  mm,	Y = -104.461  mm,	Z =  357.159  mm,
	W =  169.951 deg,	P =   -6.668 deg,	R =   91.179 deg
};
P[756]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  433.463  mm,	Y = -104.434  mm,	Z =  357.662  mm,
	W =  170.509 deg,	P =   -6.580 deg,	R =   91.098 deg
};
P[757]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  436.386  mm,	Y = -104.407  mm,	Z =  358.135  mm,
	W =  171.069 deg,	P =   -6.508 deg,	R =   91.020 deg
};
P[758]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.313  mm,	Y = -104.378  mm,	Z =  358.581  mm,
	W =  171.643 deg,	P =   -6.425 deg,	R =   90.942 deg
};
P[759]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.245  mm,	Y = -104.343  mm,	Z =  358.998  mm,
	W =  172.201 deg,	P =   -6.355 deg,	R =   90.869 deg
};
P[760]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.178  mm,	Y = -104.311  mm,	Z =  359.385  mm,
	W =  172.803 deg,	P =   -6.275 deg,	R =   90.791 deg
};
P[761]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  448.115  mm,	Y = -104.270  mm,	Z =  359.743  mm,
	W =  173.393 deg,	P =   -6.195 deg,	R =   90.716 deg
};
P[762]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  451.056  mm,	Y = -104.228  mm,	Z =  360.071  mm,
	W =  173.986 deg,	P =   -6.132 deg,	R =   90.645 deg
};
P[763]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  453.999  mm,	Y = -104.183  mm,	Z =  360.369  mm,
	W =  174.587 deg,	P =   -6.058 deg,	R =   90.573 deg
};
P[764]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  456.945  mm,	Y = -104.132  mm,	Z =  360.636  mm,
	W =  175.188 deg,	P =   -5.996 deg,	R =   90.504 deg
};
P[765]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.893  mm,	Y = -104.081  mm,	Z =  360.873  mm,
	W =  175.799 deg,	P =   -5.930 deg,	R =   90.435 deg
};
P[766]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.842  mm,	Y = -104.022  mm,	Z =  361.079  mm,
	W =  176.411 deg,	P =   -5.863 deg,	R =   90.367 deg
};
P[767]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.794  mm,	Y = -103.961  mm,	Z =  361.254  mm,
	W =  177.024 deg,	P =   -5.810 deg,	R =   90.302 deg
};
P[768]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  468.747  mm,	Y = -103.895  mm,	Z =  361.397  mm,
	W =  177.641 deg,	P =   -5.752 deg,	R =   90.237 deg
};
P[769]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  471.701  mm,	Y = -103.824  mm,	Z =  361.510  mm,
	W =  178.258 deg,	P =   -5.666 deg,	R =   90.172 deg
};
P[770]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.656  mm,	Y = -103.750  mm,	Z =  361.590  mm,
	W =  178.879 deg,	P =   -5.627 deg,	R =   90.110 deg
};
P[771]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.612  mm,	Y = -103.674  mm,	Z =  361.639  mm,
	W =  179.500 deg,	P =   -5.586 deg,	R =   90.049 deg
};
P[772]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.568  mm,	Y = -103.594  mm,	Z =  361.657  mm,
	W = -179.881 deg,	P =   -5.545 deg,	R =   89.988 deg
};
P[773]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  483.524  mm,	Y = -103.510  mm,	Z =  361.643  mm,
	W = -179.261 deg,	P =   -5.514 deg,	R =   89.929 deg
};
P[774]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  486.479  mm,	Y = -103.422  mm,	Z =  361.598  mm,
	W = -178.643 deg,	P =   -5.482 deg,	R =   89.870 deg
};
P[775]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.434  mm,	Y = -103.330  mm,	Z =  361.521  mm,
	W = -178.026 deg,	P =   -5.461 deg,	R =   89.812 deg
};
P[776]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  492.389  mm,	Y = -103.232  mm,	Z =  361.413  mm,
	W = -177.416 deg,	P =   -5.441 deg,	R =   89.755 deg
};
P[777]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  495.341  mm,	Y = -103.132  mm,	Z =  361.274  mm,
	W = -176.801 deg,	P =   -5.428 deg,	R =   89.697 deg
};
P[778]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  498.292  mm,	Y = -103.026  mm,	Z =  361.105  mm,
	W = -176.193 deg,	P =   -5.419 deg,	R =   89.640 deg
};
P[779]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  501.242  mm,	Y = -102.917  mm,	Z =  360.904  mm,
	W = -175.589 deg,	P =   -5.415 deg,	R =   89.583 deg
};
P[780]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  504.189  mm,	Y = -102.803  mm,	Z =  360.673  mm,
	W = -174.991 deg,	P =   -5.420 deg,	R =   89.526 deg
};
P[781]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.134  mm,	Y = -102.686  mm,	Z =  360.412  mm,
	W = -174.395 deg,	P =   -5.426 deg,	R =   89.468 deg
};
P[782]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.077  mm,	Y = -102.565  mm,	Z =  360.121  mm,
	W = -173.808 deg,	P =   -5.444 deg,	R =   89.410 deg
};
P[783]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  513.016  mm,	Y = -102.438  mm,	Z =  359.801  mm,
	W = -173.223 deg,	P =   -5.467 deg,	R =   89.351 deg
};
P[784]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  515.953  mm,	Y = -102.312  mm,	Z =  359.451  mm,
	W = -172.647 deg,	P =   -5.492 deg,	R =   89.292 deg
};
P[785]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  518.887  mm,	Y = -102.179  mm,	Z =  359.072  mm,
	W = -172.077 deg,	P =   -5.531 deg,	R =   89.232 deg
};
P[786]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  521.817  mm,	Y = -102.045  mm,	Z =  358.665  mm,
	W = -171.513 deg,	P =   -5.568 deg,	R =   89.170 deg
};
P[787]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  524.743  mm,	Y = -101.907  mm,	Z =  358.230  mm,
	W = -170.958 deg,	P =   -5.620 deg,	R =   89.107 deg
};
P[788]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.666  mm,	Y = -101.765  mm,	Z =  357.767  mm,
	W = -170.410 deg,	P =   -5.679 deg,	R =   89.042 deg
};
P[789]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.584  mm,	Y = -101.624  mm,	Z =  357.277  mm,
	W = -169.868 deg,	P =   -5.734 deg,	R =   88.977 deg
};
P[790]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.955  mm,	Y =  -98.720  mm,	Z =  357.488  mm,
	W = -169.969 deg,	P =   -4.815 deg,	R =   89.149 deg
};
P[791]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.933  mm,	Y =  -95.792  mm,	Z =  357.722  mm,
	W = -170.176 deg,	P =   -3.936 deg,	R =   89.319 deg
};
P[792]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.908  mm,	Y =  -92.858  mm,	Z =  357.912  mm,
	W = -170.406 deg,	P =   -3.092 deg,	R =   89.478 deg
};
P[793]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.888  mm,	Y =  -89.916  mm,	Z =  358.058  mm,
	W = -170.665 deg,	P =   -2.341 deg,	R =   89.615 deg
};
P[794]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.869  mm,	Y =  -86.967  mm,	Z =  358.166  mm,
	W = -170.937 deg,	P =   -1.646 deg,	R =   89.738 deg
};
P[795]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.849  mm,	Y =  -84.011  mm,	Z =  358.240  mm,
	W = -171.239 deg,	P =   -1.042 deg,	R =   89.839 deg
};
P[796]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.835  mm,	Y =  -81.047  mm,	Z =  358.284  mm,
	W = -171.548 deg,	P =   -0.548 deg,	R =   89.919 deg
};
P[797]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.712  mm,	Y =  -78.082  mm,	Z =  358.318  mm,
	W = -171.884 deg,	P =   -0.103 deg,	R =   89.985 deg
};
P[798]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.553  mm,	Y =  -75.109  mm,	Z =  358.338  mm,
	W = -172.230 deg,	P =    0.204 deg,	R =   90.028 deg
};
P[799]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.376  mm,	Y =  -72.132  mm,	Z =  358.343  mm,
	W = -172.574 deg,	P =    0.433 deg,	R =   90.056 deg
};
P[800]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.217  mm,	Y =  -69.148  mm,	Z =  358.337  mm,
	W = -172.916 deg,	P =    0.572 deg,	R =   90.071 deg
};
P[801]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  530.056  mm,	Y =  -66.153  mm,	Z =  358.326  mm,
	W = -173.240 deg,	P =    0.566 deg,	R =   90.067 deg
};
P[802]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.896  mm,	Y =  -63.155  mm,	Z =  358.315  mm,
	W = -173.555 deg,	P =    0.514 deg,	R =   90.058 deg
};
P[803]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.782  mm,	Y =  -60.143  mm,	Z =  358.306  mm,
	W = -173.843 deg,	P =    0.309 deg,	R =   90.033 deg
};
P[804]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.601  mm,	Y =  -57.132  mm,	Z =  358.314  mm,
	W = -174.109 deg,	P =    0.057 deg,	R =   90.006 deg
};
P[805]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.475  mm,	Y =  -54.113  mm,	Z =  358.332  mm,
	W = -174.344 deg,	P =   -0.270 deg,	R =   89.973 deg
};
P[806]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.332  mm,	Y =  -51.086  mm,	Z =  358.372  mm,
	W = -174.551 deg,	P =   -0.713 deg,	R =   89.932 deg
};
P[807]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.193  mm,	Y =  -48.058  mm,	Z =  358.435  mm,
	W = -174.722 deg,	P =   -1.175 deg,	R =   89.891 deg
};
P[808]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  529.078  mm,	Y =  -45.024  mm,	Z =  358.523  mm,
	W = -174.859 deg,	P =   -1.718 deg,	R =   89.845 deg
};
P[809]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.942  mm,	Y =  -41.990  mm,	Z =  358.641  mm,
	W = -174.945 deg,	P =   -2.279 deg,	R =   89.798 deg
};
P[810]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.833  mm,	Y =  -38.955  mm,	Z =  358.788  mm,
	W = -175.015 deg,	P =   -2.866 deg,	R =   89.750 deg
};
P[811]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.716  mm,	Y =  -35.921  mm,	Z =  358.967  mm,
	W = -175.011 deg,	P =   -3.465 deg,	R =   89.698 deg
};
P[812]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.613  mm,	Y =  -32.890  mm,	Z =  359.177  mm,
	W = -174.983 deg,	P =   -4.026 deg,	R =   89.647 deg
};
P[813]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.503  mm,	Y =  -29.859  mm,	Z =  359.419  mm,
	W = -174.920 deg,	P =   -4.628 deg,	R =   89.589 deg
};
P[814]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.417  mm,	Y =  -26.834  mm,	Z =  359.688  mm,
	W = -174.807 deg,	P =   -5.182 deg,	R =   89.530 deg
};
P[815]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.318  mm,	Y =  -23.815  mm,	Z =  359.986  mm,
	W = -174.661 deg,	P =   -5.667 deg,	R =   89.471 deg
};
P[816]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.234  mm,	Y =  -20.802  mm,	Z =  360.308  mm,
	W = -174.488 deg,	P =   -6.110 deg,	R =   89.411 deg
};
P[817]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.163  mm,	Y =  -17.795  mm,	Z =  360.650  mm,
	W = -174.282 deg,	P =   -6.488 deg,	R =   89.352 deg
};
P[818]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.068  mm,	Y =  -14.798  mm,	Z =  361.013  mm,
	W = -174.049 deg,	P =   -6.772 deg,	R =   89.296 deg
};
P[819]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  528.025  mm,	Y =  -11.804  mm,	Z =  361.383  mm,
	W = -173.793 deg,	P =   -7.006 deg,	R =   89.240 deg
};
P[820]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.942  mm,	Y =   -8.822  mm,	Z =  361.766  mm,
	W = -173.522 deg,	P =   -7.097 deg,	R =   89.196 deg
};
P[821]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.889  mm,	Y =   -5.844  mm,	Z =  362.149  mm,
	W = -173.233 deg,	P =   -7.123 deg,	R =   89.157 deg
};
P[822]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.841  mm,	Y =   -2.874  mm,	Z =  362.530  mm,
	W = -172.943 deg,	P =   -7.042 deg,	R =   89.131 deg
};
P[823]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.769  mm,	Y =    0.088  mm,	Z =  362.906  mm,
	W = -172.644 deg,	P =   -6.843 deg,	R =   89.119 deg
};
P[824]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.750  mm,	Y =    3.051  mm,	Z =  363.264  mm,
	W = -172.350 deg,	P =   -6.601 deg,	R =   89.115 deg
};
P[825]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.677  mm,	Y =    5.999  mm,	Z =  363.609  mm,
	W = -172.060 deg,	P =   -6.152 deg,	R =   89.144 deg
};
P[826]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.639  mm,	Y =    8.948  mm,	Z =  363.927  mm,
	W = -171.769 deg,	P =   -5.661 deg,	R =   89.183 deg
};
P[827]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.583  mm,	Y =   11.892  mm,	Z =  364.217  mm,
	W = -171.520 deg,	P =   -5.062 deg,	R =   89.246 deg
};
P[828]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.521  mm,	Y =   14.831  mm,	Z =  364.475  mm,
	W = -171.270 deg,	P =   -4.360 deg,	R =   89.331 deg
};
P[829]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.486  mm,	Y =   17.770  mm,	Z =  364.690  mm,
	W = -171.052 deg,	P =   -3.607 deg,	R =   89.432 deg
};
P[830]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.414  mm,	Y =   20.702  mm,	Z =  364.868  mm,
	W = -170.857 deg,	P =   -2.720 deg,	R =   89.562 deg
};
P[831]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.357  mm,	Y =   23.635  mm,	Z =  364.997  mm,
	W = -170.695 deg,	P =   -1.817 deg,	R =   89.702 deg
};
P[832]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.289  mm,	Y =   26.562  mm,	Z =  365.077  mm,
	W = -170.557 deg,	P =   -0.811 deg,	R =   89.865 deg
};
P[833]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.204  mm,	Y =   29.487  mm,	Z =  365.107  mm,
	W = -170.446 deg,	P =    0.237 deg,	R =   90.040 deg
};
P[834]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.126  mm,	Y =   32.411  mm,	Z =  365.080  mm,
	W = -170.387 deg,	P =    1.287 deg,	R =   90.218 deg
};
P[835]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  527.025  mm,	Y =   35.330  mm,	Z =  365.000  mm,
	W = -170.354 deg,	P =    2.399 deg,	R =   90.408 deg
};
P[836]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.919  mm,	Y =   38.247  mm,	Z =  364.864  mm,
	W = -170.359 deg,	P =    3.493 deg,	R =   90.593 deg
};
P[837]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.809  mm,	Y =   41.161  mm,	Z =  364.671  mm,
	W = -170.402 deg,	P =    4.594 deg,	R =   90.776 deg
};
P[838]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.686  mm,	Y =   44.070  mm,	Z =  364.422  mm,
	W = -170.475 deg,	P =    5.685 deg,	R =   90.952 deg
};
P[839]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.558  mm,	Y =   46.978  mm,	Z =  364.119  mm,
	W = -170.588 deg,	P =    6.722 deg,	R =   91.112 deg
};
P[840]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.416  mm,	Y =   49.881  mm,	Z =  363.763  mm,
	W = -170.728 deg,	P =    7.740 deg,	R =   91.260 deg
};
P[841]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.266  mm,	Y =   52.780  mm,	Z =  363.358  mm,
	W = -170.905 deg,	P =    8.711 deg,	R =   91.389 deg
};
P[842]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  526.117  mm,	Y =   55.680  mm,	Z =  362.902  mm,
	W = -171.111 deg,	P =    9.575 deg,	R =   91.490 deg
};
P[843]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.949  mm,	Y =   58.574  mm,	Z =  362.406  mm,
	W = -171.341 deg,	P =   10.408 deg,	R =   91.576 deg
};
P[844]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.793  mm,	Y =   61.469  mm,	Z =  361.866  mm,
	W = -171.597 deg,	P =   11.125 deg,	R =   91.633 deg
};
P[845]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.618  mm,	Y =   64.361  mm,	Z =  361.292  mm,
	W = -171.869 deg,	P =   11.779 deg,	R =   91.671 deg
};
P[846]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.449  mm,	Y =   67.254  mm,	Z =  360.685  mm,
	W = -172.164 deg,	P =   12.337 deg,	R =   91.684 deg
};
P[847]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.278  mm,	Y =   70.149  mm,	Z =  360.050  mm,
	W = -172.461 deg,	P =   12.781 deg,	R =   91.677 deg
};
P[848]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  525.102  mm,	Y =   73.043  mm,	Z =  359.395  mm,
	W = -172.777 deg,	P =   13.169 deg,	R =   91.654 deg
};
P[849]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  524.939  mm,	Y =   75.946  mm,	Z =  358.719  mm,
	W = -173.085 deg,	P =   13.390 deg,	R =   91.609 deg
};
P[850]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  524.530  mm,	Y =   78.829  mm,	Z =  358.064  mm,
	W = -173.435 deg,	P =   13.578 deg,	R =   91.548 deg
};
P[851]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  522.423  mm,	Y =   80.897  mm,	Z =  357.781  mm,
	W = -173.941 deg,	P =   13.795 deg,	R =   91.450 deg
};
P[852]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  520.316  mm,	Y =   82.966  mm,	Z =  357.472  mm,
	W = -174.419 deg,	P =   13.997 deg,	R =   91.354 deg
};
P[853]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  518.208  mm,	Y =   85.041  mm,	Z =  357.141  mm,
	W = -174.885 deg,	P =   14.048 deg,	R =   91.245 deg
};
P[854]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  516.102  mm,	Y =   87.118  mm,	Z =  356.792  mm,
	W = -175.319 deg,	P =   14.080 deg,	R =   91.141 deg
};
P[855]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  513.994  mm,	Y =   89.199  mm,	Z =  356.427  mm,
	W = -175.738 deg,	P =   14.015 deg,	R =   91.034 deg
};
P[856]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.885  mm,	Y =   91.284  mm,	Z =  356.052  mm,
	W = -176.132 deg,	P =   13.880 deg,	R =   90.929 deg
};
P[857]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.093  mm,	Y =   92.308  mm,	Z =  355.971  mm,
	W = -176.527 deg,	P =   13.903 deg,	R =   90.835 deg
};
P[858]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.125  mm,	Y =   92.182  mm,	Z =  356.169  mm,
	W = -176.881 deg,	P =   14.051 deg,	R =   90.758 deg
};
P[859]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  503.157  mm,	Y =   92.055  mm,	Z =  356.348  mm,
	W = -177.248 deg,	P =   14.192 deg,	R =   90.675 deg
};
P[860]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.186  mm,	Y =   91.934  mm,	Z =  356.509  mm,
	W = -177.586 deg,	P =   14.321 deg,	R =   90.598 deg
};
P[861]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  497.215  mm,	Y =   91.811  mm,	Z =  356.653  mm,
	W = -177.943 deg,	P =   14.433 deg,	R =   90.513 deg
};
P[862]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  494.242  mm,	Y =   91.693  mm,	Z =  356.778  mm,
	W = -178.290 deg,	P =   14.536 deg,	R =   90.429 deg
};
P[863]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  491.270  mm,	Y =   91.575  mm,	Z =  356.886  mm,
	W = -178.649 deg,	P =   14.616 deg,	R =   90.341 deg
};
P[864]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.297  mm,	Y =   91.458  mm,	Z =  356.975  mm,
	W = -179.011 deg,	P =   14.685 deg,	R =   90.251 deg
};
P[865]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.322  mm,	Y =   91.345  mm,	Z =  357.046  mm,
	W = -179.357 deg,	P =   14.740 deg,	R =   90.164 deg
};
P[866]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.348  mm,	Y =   91.230  mm,	Z =  357.099  mm,
	W = -179.719 deg,	P =   14.778 deg,	R =   90.072 deg
};
P[867]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.374  mm,	Y =   91.121  mm,	Z =  357.133  mm,
	W =  179.927 deg,	P =   14.798 deg,	R =   89.981 deg
};
P[868]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.399  mm,	Y =   91.011  mm,	Z =  357.149  mm,
	W =  179.566 deg,	P =   14.805 deg,	R =   89.889 deg
};
P[869]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.425  mm,	Y =   90.903  mm,	Z =  357.147  mm,
	W =  179.202 deg,	P =   14.794 deg,	R =   89.796 deg
};
P[870]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.450  mm,	Y =   90.797  mm,	Z =  357.126  mm,
	W =  178.846 deg,	P =   14.769 deg,	R =   89.706 deg
};
P[871]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.477  mm,	Y =   90.691  mm,	Z =  357.087  mm,
	W =  178.471 deg,	P =   14.724 deg,	R =   89.611 deg
};
P[872]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.503  mm,	Y =   90.589  mm,	Z =  357.028  mm,
	W =  178.116 deg,	P =   14.665 deg,	R =   89.523 deg
};
P[873]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.530  mm,	Y =   90.488  mm,	Z =  356.950  mm,
	W =  177.746 deg,	P =   14.588 deg,	R =   89.432 deg
};
P[874]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  458.558  mm,	Y =   90.389  mm,	Z =  356.854  mm,
	W =  177.374 deg,	P =   14.494 deg,	R =   89.342 deg
};
P[875]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  455.586  mm,	Y =   90.292  mm,	Z =  356.737  mm,
	W =  177.008 deg,	P =   14.387 deg,	R =   89.256 deg
};
P[876]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  452.616  mm,	Y =   90.197  mm,	Z =  356.602  mm,
	W =  176.625 deg,	P =   14.257 deg,	R =   89.168 deg
};
P[877]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  449.646  mm,	Y =   90.104  mm,	Z =  356.446  mm,
	W =  176.257 deg,	P =   14.118 deg,	R =   89.086 deg
};
P[878]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  447.335  mm,	Y =   88.244  mm,	Z =  356.763  mm,
	W =  175.845 deg,	P =   14.211 deg,	R =   88.978 deg
};
P[879]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.460  mm,	Y =   85.961  mm,	Z =  357.208  mm,
	W =  175.446 deg,	P =   14.264 deg,	R =   88.876 deg
};
P[880]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.586  mm,	Y =   83.681  mm,	Z =  357.640  mm,
	W =  175.017 deg,	P =   14.260 deg,	R =   88.770 deg
};
P[881]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.712  mm,	Y =   81.405  mm,	Z =  358.057  mm,
	W =  174.569 deg,	P =   14.163 deg,	R =   88.667 deg
};
P[882]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.838  mm,	Y =   79.133  mm,	Z =  358.452  mm,
	W =  174.105 deg,	P =   13.987 deg,	R =   88.570 deg
};
P[883]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.683  mm,	Y =   76.232  mm,	Z =  359.164  mm,
	W =  173.821 deg,	P =   13.860 deg,	R =   88.514 deg
};
P[884]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.715  mm,	Y =   73.334  mm,	Z =  359.886  mm,
	W =  173.559 deg,	P =   13.655 deg,	R =   88.473 deg
};
P[885]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.757  mm,	Y =   70.443  mm,	Z =  360.593  mm,
	W =  173.313 deg,	P =   13.310 deg,	R =   88.454 deg
};
P[886]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.795  mm,	Y =   67.550  mm,	Z =  361.281  mm,
	W =  173.062 deg,	P =   12.914 deg,	R =   88.442 deg
};
P[887]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.829  mm,	Y =   64.665  mm,	Z =  361.941  mm,
	W =  172.835 deg,	P =   12.338 deg,	R =   88.461 deg
};
P[888]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.877  mm,	Y =   61.776  mm,	Z =  362.573  mm,
	W =  172.617 deg,	P =   11.714 deg,	R =   88.493 deg
};
P[889]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.912  mm,	Y =   58.888  mm,	Z =  363.167  mm,
	W =  172.420 deg,	P =   10.972 deg,	R =   88.549 deg
};
P[890]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  439.967  mm,	Y =   56.000  mm,	Z =  363.723  mm,
	W =  172.248 deg,	P =   10.129 deg,	R =   88.629 deg
};
P[891]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.022  mm,	Y =   53.107  mm,	Z =  364.233  mm,
	W =  172.095 deg,	P =    9.246 deg,	R =   88.722 deg
};
P[892]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.083  mm,	Y =   50.216  mm,	Z =  364.694  mm,
	W =  171.975 deg,	P =    8.212 deg,	R =   88.846 deg
};
P[893]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.161  mm,	Y =   47.319  mm,	Z =  365.105  mm,
	W =  171.882 deg,	P =    7.172 deg,	R =   88.980 deg
};
P[894]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.238  mm,	Y =   44.420  mm,	Z =  365.458  mm,
	W =  171.823 deg,	P =    6.046 deg,	R =   89.133 deg
};
P[895]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.334  mm,	Y =   41.519  mm,	Z =  365.756  mm,
	W =  171.791 deg,	P =    4.886 deg,	R =   89.296 deg
};
P[896]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.438  mm,	Y =   38.612  mm,	Z =  365.994  mm,
	W =  171.792 deg,	P =    3.720 deg,	R =   89.464 deg
};
P[897]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.552  mm,	Y =   35.706  mm,	Z =  366.172  mm,
	W =  171.822 deg,	P =    2.498 deg,	R =   89.641 deg
};
P[898]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.674  mm,	Y =   32.796  mm,	Z =  366.288  mm,
	W =  171.887 deg,	P =    1.298 deg,	R =   89.815 deg
};
P[899]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.810  mm,	Y =   29.883  mm,	Z =  366.344  mm,
	W =  171.975 deg,	P =    0.122 deg,	R =   89.983 deg
};
P[900]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  440.952  mm,	Y =   26.967  mm,	Z =  366.341  mm,
	W =  172.106 deg,	P =   -1.026 deg,	R =   90.142 deg
};
P[901]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.104  mm,	Y =   24.050  mm,	Z =  366.280  mm,
	W =  172.243 deg,	P =   -2.126 deg,	R =   90.290 deg
};
P[902]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.270  mm,	Y =   21.130  mm,	Z =  366.165  mm,
	W =  172.436 deg,	P =   -3.155 deg,	R =   90.419 deg
};
P[903]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.432  mm,	Y =   18.208  mm,	Z =  365.996  mm,
	W =  172.635 deg,	P =   -4.120 deg,	R =   90.532 deg
};
P[904]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.611  mm,	Y =   15.283  mm,	Z =  365.782  mm,
	W =  172.858 deg,	P =   -4.990 deg,	R =   90.624 deg
};
P[905]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.770  mm,	Y =   12.356  mm,	Z =  365.520  mm,
	W =  173.097 deg,	P =   -5.791 deg,	R =   90.700 deg
};
P[906]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  441.949  mm,	Y =    9.423  mm,	Z =  365.222  mm,
	W =  173.351 deg,	P =   -6.453 deg,	R =   90.751 deg
};
P[907]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.097  mm,	Y =    6.486  mm,	Z =  364.886  mm,
	W =  173.623 deg,	P =   -7.017 deg,	R =   90.782 deg
};
P[908]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.302  mm,	Y =    3.549  mm,	Z =  364.530  mm,
	W =  173.892 deg,	P =   -7.489 deg,	R =   90.799 deg
};
P[909]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.459  mm,	Y =    0.600  mm,	Z =  364.146  mm,
	W =  174.170 deg,	P =   -7.794 deg,	R =   90.793 deg
};
P[910]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.651  mm,	Y =   -2.348  mm,	Z =  363.750  mm,
	W =  174.439 deg,	P =   -8.056 deg,	R =   90.782 deg
};
P[911]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.829  mm,	Y =   -5.311  mm,	Z =  363.343  mm,
	W =  174.717 deg,	P =   -8.107 deg,	R =   90.747 deg
};
P[912]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  442.990  mm,	Y =   -8.279  mm,	Z =  362.930  mm,
	W =  174.984 deg,	P =   -8.086 deg,	R =   90.707 deg
};
P[913]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.179  mm,	Y =  -11.253  mm,	Z =  362.523  mm,
	W =  175.230 deg,	P =   -7.962 deg,	R =   90.662 deg
};
P[914]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.323  mm,	Y =  -14.241  mm,	Z =  362.120  mm,
	W =  175.465 deg,	P =   -7.692 deg,	R =   90.608 deg
};
P[915]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.490  mm,	Y =  -17.233  mm,	Z =  361.735  mm,
	W =  175.679 deg,	P =   -7.389 deg,	R =   90.557 deg
};
P[916]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.638  mm,	Y =  -20.240  mm,	Z =  361.367  mm,
	W =  175.871 deg,	P =   -6.902 deg,	R =   90.497 deg
};
P[917]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.782  mm,	Y =  -23.253  mm,	Z =  361.023  mm,
	W =  176.037 deg,	P =   -6.390 deg,	R =   90.442 deg
};
P[918]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  443.925  mm,	Y =  -26.275  mm,	Z =  360.709  mm,
	W =  176.179 deg,	P =   -5.786 deg,	R =   90.386 deg
};
P[919]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.053  mm,	Y =  -29.306  mm,	Z =  360.426  mm,
	W =  176.290 deg,	P =   -5.112 deg,	R =   90.331 deg
};
P[920]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.181  mm,	Y =  -32.341  mm,	Z =  360.180  mm,
	W =  176.373 deg,	P =   -4.432 deg,	R =   90.281 deg
};
P[921]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.299  mm,	Y =  -35.385  mm,	Z =  359.972  mm,
	W =  176.423 deg,	P =   -3.664 deg,	R =   90.229 deg
};
P[922]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.412  mm,	Y =  -38.430  mm,	Z =  359.802  mm,
	W =  176.442 deg,	P =   -2.917 deg,	R =   90.181 deg
};
P[923]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.517  mm,	Y =  -41.478  mm,	Z =  359.673  mm,
	W =  176.427 deg,	P =   -2.173 deg,	R =   90.136 deg
};
P[924]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.621  mm,	Y =  -44.526  mm,	Z =  359.583  mm,
	W =  176.385 deg,	P =   -1.432 deg,	R =   90.090 deg
};
P[925]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.709  mm,	Y =  -47.573  mm,	Z =  359.531  mm,
	W =  176.310 deg,	P =   -0.750 deg,	R =   90.048 deg
};
P[926]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.798  mm,	Y =  -50.617  mm,	Z =  359.515  mm,
	W =  176.213 deg,	P =   -0.093 deg,	R =   90.006 deg
};
P[927]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.876  mm,	Y =  -53.658  mm,	Z =  359.531  mm,
	W =  176.080 deg,	P =    0.505 deg,	R =   89.965 deg
};
P[928]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  444.946  mm,	Y =  -56.691  mm,	Z =  359.575  mm,
	W =  175.929 deg,	P =    0.979 deg,	R =   89.930 deg
};
P[929]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.019  mm,	Y =  -59.719  mm,	Z =  359.644  mm,
	W =  175.755 deg,	P =    1.398 deg,	R =   89.896 deg
};
P[930]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.069  mm,	Y =  -62.738  mm,	Z =  359.730  mm,
	W =  175.562 deg,	P =    1.695 deg,	R =   89.868 deg
};
P[931]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.128  mm,	Y =  -65.749  mm,	Z =  359.831  mm,
	W =  175.358 deg,	P =    1.885 deg,	R =   89.847 deg
};
P[932]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.172  mm,	Y =  -68.755  mm,	Z =  359.937  mm,
	W =  175.135 deg,	P =    1.987 deg,	R =   89.831 deg
};
P[933]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.212  mm,	Y =  -71.747  mm,	Z =  360.043  mm,
	W =  174.914 deg,	P =    1.909 deg,	R =   89.830 deg
};
P[934]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.256  mm,	Y =  -74.735  mm,	Z =  360.145  mm,
	W =  174.680 deg,	P =    1.752 deg,	R =   89.837 deg
};
P[935]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.281  mm,	Y =  -77.712  mm,	Z =  360.231  mm,
	W =  174.450 deg,	P =    1.441 deg,	R =   89.860 deg
};
P[936]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  445.321  mm,	Y =  -80.680  mm,	Z =  360.300  mm,
	W =  174.224 deg,	P =    1.004 deg,	R =   89.898 deg
};
P[937]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  446.898  mm,	Y =  -83.199  mm,	Z =  360.496  mm,
	W =  174.285 deg,	P =    0.676 deg,	R =   89.932 deg
};
P[938]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  449.589  mm,	Y =  -84.435  mm,	Z =  360.770  mm,
	W =  174.673 deg,	P =    0.607 deg,	R =   89.943 deg
};
P[939]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  452.526  mm,	Y =  -84.771  mm,	Z =  361.036  mm,
	W =  175.145 deg,	P =    0.702 deg,	R =   89.940 deg
};
P[940]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  455.478  mm,	Y =  -84.705  mm,	Z =  361.271  mm,
	W =  175.679 deg,	P =    0.891 deg,	R =   89.933 deg
};
P[941]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  458.433  mm,	Y =  -84.628  mm,	Z =  361.480  mm,
	W =  176.202 deg,	P =    1.071 deg,	R =   89.929 deg
};
P[942]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.390  mm,	Y =  -84.549  mm,	Z =  361.661  mm,
	W =  176.719 deg,	P =    1.216 deg,	R =   89.930 deg
};
P[943]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.348  mm,	Y =  -84.466  mm,	Z =  361.815  mm,
	W =  177.244 deg,	P =    1.358 deg,	R =   89.935 deg
};
P[944]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.307  mm,	Y =  -84.376  mm,	Z =  361.942  mm,
	W =  177.763 deg,	P =    1.475 deg,	R =   89.942 deg
};
P[945]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.267  mm,	Y =  -84.282  mm,	Z =  362.042  mm,
	W =  178.287 deg,	P =    1.576 deg,	R =   89.953 deg
};
P[946]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.228  mm,	Y =  -84.180  mm,	Z =  362.114  mm,
	W =  178.810 deg,	P =    1.670 deg,	R =   89.965 deg
};
P[947]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.189  mm,	Y =  -84.078  mm,	Z =  362.159  mm,
	W =  179.330 deg,	P =    1.724 deg,	R =   89.980 deg
};
P[948]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.151  mm,	Y =  -83.972  mm,	Z =  362.177  mm,
	W =  179.851 deg,	P =    1.775 deg,	R =   89.995 deg
};
P[949]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.112  mm,	Y =  -83.861  mm,	Z =  362.167  mm,
	W = -179.629 deg,	P =    1.805 deg,	R =   90.012 deg
};
P[950]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.074  mm,	Y =  -83.742  mm,	Z =  362.131  mm,
	W = -179.112 deg,	P =    1.791 deg,	R =   90.028 deg
};
P[951]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.035  mm,	Y =  -83.621  mm,	Z =  362.068  mm,
	W = -178.597 deg,	P =    1.768 deg,	R =   90.043 deg
};
P[952]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.995  mm,	Y =  -83.494  mm,	Z =  361.979  mm,
	W = -178.082 deg,	P =    1.732 deg,	R =   90.058 deg
};
P[953]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  493.955  mm,	Y =  -83.361  mm,	Z =  361.863  mm,
	W = -177.574 deg,	P =    1.666 deg,	R =   90.071 deg
};
P[954]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  496.913  mm,	Y =  -83.227  mm,	Z =  361.720  mm,
	W = -177.062 deg,	P =    1.597 deg,	R =   90.082 deg
};
P[955]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  499.870  mm,	Y =  -83.083  mm,	Z =  361.552  mm,
	W = -176.562 deg,	P =    1.489 deg,	R =   90.089 deg
};
P[956]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  502.826  mm,	Y =  -82.938  mm,	Z =  361.358  mm,
	W = -176.065 deg,	P =    1.371 deg,	R =   90.094 deg
};
P[957]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.779  mm,	Y =  -82.787  mm,	Z =  361.139  mm,
	W = -175.563 deg,	P =    1.239 deg,	R =   90.096 deg
};
P[958]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.731  mm,	Y =  -82.631  mm,	Z =  360.894  mm,
	W = -175.075 deg,	P =    1.081 deg,	R =   90.093 deg
};
P[959]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.277  mm,	Y =  -81.110  mm,	Z =  360.637  mm,
	W = -174.751 deg,	P =    1.180 deg,	R =   90.108 deg
};
P[960]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.209  mm,	Y =  -78.146  mm,	Z =  360.568  mm,
	W = -174.969 deg,	P =    1.670 deg,	R =   90.147 deg
};
P[961]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.141  mm,	Y =  -75.170  mm,	Z =  360.478  mm,
	W = -175.197 deg,	P =    1.979 deg,	R =   90.166 deg
};
P[962]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.073  mm,	Y =  -72.187  mm,	Z =  360.373  mm,
	W = -175.413 deg,	P =    2.178 deg,	R =   90.175 deg
};
P[963]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  511.005  mm,	Y =  -69.196  mm,	Z =  360.262  mm,
	W = -175.641 deg,	P =    2.268 deg,	R =   90.173 deg
};
P[964]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.936  mm,	Y =  -66.193  mm,	Z =  360.149  mm,
	W = -175.852 deg,	P =    2.171 deg,	R =   90.157 deg
};
P[965]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.866  mm,	Y =  -63.185  mm,	Z =  360.043  mm,
	W = -176.055 deg,	P =    2.020 deg,	R =   90.139 deg
};
P[966]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.768  mm,	Y =  -60.166  mm,	Z =  359.951  mm,
	W = -176.247 deg,	P =    1.695 deg,	R =   90.111 deg
};
P[967]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.545  mm,	Y =  -57.148  mm,	Z =  359.885  mm,
	W = -176.437 deg,	P =    1.293 deg,	R =   90.080 deg
};
P[968]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.346  mm,	Y =  -54.122  mm,	Z =  359.841  mm,
	W = -176.607 deg,	P =    0.809 deg,	R =   90.048 deg
};
P[969]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  510.156  mm,	Y =  -51.085  mm,	Z =  359.825  mm,
	W = -176.752 deg,	P =    0.186 deg,	R =   90.011 deg
};
P[970]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.956  mm,	Y =  -48.047  mm,	Z =  359.843  mm,
	W = -176.876 deg,	P =   -0.462 deg,	R =   89.975 deg
};
P[971]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.787  mm,	Y =  -45.000  mm,	Z =  359.897  mm,
	W = -176.974 deg,	P =   -1.211 deg,	R =   89.936 deg
};
P[972]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.608  mm,	Y =  -41.953  mm,	Z =  359.990  mm,
	W = -177.039 deg,	P =   -1.979 deg,	R =   89.898 deg
};
P[973]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.444  mm,	Y =  -38.906  mm,	Z =  360.126  mm,
	W = -177.080 deg,	P =   -2.766 deg,	R =   89.859 deg
};
P[974]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.283  mm,	Y =  -35.858  mm,	Z =  360.304  mm,
	W = -177.098 deg,	P =   -3.594 deg,	R =   89.818 deg
};
P[975]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  509.135  mm,	Y =  -32.815  mm,	Z =  360.524  mm,
	W = -177.086 deg,	P =   -4.374 deg,	R =   89.778 deg
};
P[976]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.984  mm,	Y =  -29.774  mm,	Z =  360.787  mm,
	W = -177.053 deg,	P =   -5.174 deg,	R =   89.734 deg
};
P[977]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.852  mm,	Y =  -26.739  mm,	Z =  361.090  mm,
	W = -176.986 deg,	P =   -5.923 deg,	R =   89.689 deg
};
P[978]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.722  mm,	Y =  -23.714  mm,	Z =  361.429  mm,
	W = -176.910 deg,	P =   -6.596 deg,	R =   89.645 deg
};
P[979]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.595  mm,	Y =  -20.697  mm,	Z =  361.803  mm,
	W = -176.796 deg,	P =   -7.204 deg,	R =   89.598 deg
};
P[980]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.490  mm,	Y =  -17.688  mm,	Z =  362.205  mm,
	W = -176.672 deg,	P =   -7.735 deg,	R =   89.552 deg
};
P[981]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.370  mm,	Y =  -14.691  mm,	Z =  362.633  mm,
	W = -176.531 deg,	P =   -8.153 deg,	R =   89.507 deg
};
P[982]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.282  mm,	Y =  -11.700  mm,	Z =  363.078  mm,
	W = -176.374 deg,	P =   -8.509 deg,	R =   89.463 deg
};
P[983]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.184  mm,	Y =   -8.723  mm,	Z =  363.537  mm,
	W = -176.208 deg,	P =   -8.690 deg,	R =   89.426 deg
};
P[984]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.096  mm,	Y =   -5.753  mm,	Z =  364.002  mm,
	W = -176.033 deg,	P =   -8.789 deg,	R =   89.393 deg
};
P[985]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  508.019  mm,	Y =   -2.792  mm,	Z =  364.467  mm,
	W = -175.850 deg,	P =   -8.760 deg,	R =   89.367 deg
};
P[986]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.932  mm,	Y =    0.159  mm,	Z =  364.927  mm,
	W = -175.671 deg,	P =   -8.580 deg,	R =   89.353 deg
};
P[987]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.867  mm,	Y =    3.108  mm,	Z =  365.373  mm,
	W = -175.493 deg,	P =   -8.329 deg,	R =   89.346 deg
};
P[988]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.789  mm,	Y =    6.044  mm,	Z =  365.800  mm,
	W = -175.314 deg,	P =   -7.861 deg,	R =   89.358 deg
};
P[989]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.715  mm,	Y =    8.979  mm,	Z =  366.201  mm,
	W = -175.138 deg,	P =   -7.325 deg,	R =   89.379 deg
};
P[990]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.637  mm,	Y =   11.907  mm,	Z =  366.569  mm,
	W = -174.995 deg,	P =   -6.641 deg,	R =   89.420 deg
};
P[991]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.551  mm,	Y =   14.831  mm,	Z =  366.900  mm,
	W = -174.846 deg,	P =   -5.834 deg,	R =   89.475 deg
};
P[992]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.478  mm,	Y =   17.755  mm,	Z =  367.185  mm,
	W = -174.725 deg,	P =   -4.953 deg,	R =   89.543 deg
};
P[993]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.386  mm,	Y =   20.671  mm,	Z =  367.422  mm,
	W = -174.613 deg,	P =   -3.907 deg,	R =   89.632 deg
};
P[994]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.292  mm,	Y =   23.589  mm,	Z =  367.605  mm,
	W = -174.526 deg,	P =   -2.828 deg,	R =   89.729 deg
};
P[995]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.191  mm,	Y =   26.500  mm,	Z =  367.728  mm,
	W = -174.453 deg,	P =   -1.625 deg,	R =   89.842 deg
};
P[996]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  507.070  mm,	Y =   29.409  mm,	Z =  367.792  mm,
	W = -174.399 deg,	P =   -0.369 deg,	R =   89.964 deg
};
P[997]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.950  mm,	Y =   32.317  mm,	Z =  367.790  mm,
	W = -174.378 deg,	P =    0.906 deg,	R =   90.089 deg
};
P[998]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.807  mm,	Y =   35.219  mm,	Z =  367.723  mm,
	W = -174.374 deg,	P =    2.247 deg,	R =   90.221 deg
};
P[999]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.655  mm,	Y =   38.118  mm,	Z =  367.590  mm,
	W = -174.393 deg,	P =    3.582 deg,	R =   90.351 deg
};
P[1000]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.495  mm,	Y =   41.014  mm,	Z =  367.388  mm,
	W = -174.438 deg,	P =    4.901 deg,	R =   90.477 deg
};
P[1001]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.320  mm,	Y =   43.905  mm,	Z =  367.121  mm,
	W = -174.499 deg,	P =    6.214 deg,	R =   90.597 deg
};
P[1002]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  506.135  mm,	Y =   46.792  mm,	Z =  366.789  mm,
	W = -174.588 deg,	P =    7.458 deg,	R =   90.704 deg
};
P[1003]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.938  mm,	Y =   49.674  mm,	Z =  366.395  mm,
	W = -174.691 deg,	P =    8.664 deg,	R =   90.802 deg
};
P[1004]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.730  mm,	Y =   52.552  mm,	Z =  365.943  mm,
	W = -174.820 deg,	P =    9.793 deg,	R =   90.883 deg
};
P[1005]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.515  mm,	Y =   55.427  mm,	Z =  365.434  mm,
	W = -174.962 deg,	P =   10.821 deg,	R =   90.948 deg
};
P[1006]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  505.291  mm,	Y =   58.296  mm,	Z =  364.874  mm,
	W = -175.123 deg,	P =   11.790 deg,	R =   90.999 deg
};
P[1007]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  504.800  mm,	Y =   61.137  mm,	Z =  364.296  mm,
	W = -175.341 deg,	P =   12.612 deg,	R =   91.019 deg
};
P[1008]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  502.577  mm,	Y =   63.049  mm,	Z =  364.021  mm,
	W = -175.852 deg,	P =   13.254 deg,	R =   90.953 deg
};
P[1009]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  500.359  mm,	Y =   64.972  mm,	Z =  363.704  mm,
	W = -176.318 deg,	P =   13.777 deg,	R =   90.878 deg
};
P[1010]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  498.140  mm,	Y =   66.887  mm,	Z =  363.353  mm,
	W = -176.802 deg,	P =   14.288 deg,	R =   90.790 deg
};
P[1011]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  495.924  mm,	Y =   68.808  mm,	Z =  362.966  mm,
	W = -177.252 deg,	P =   14.715 deg,	R =   90.699 deg
};
P[1012]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  493.710  mm,	Y =   70.732  mm,	Z =  362.548  mm,
	W = -177.700 deg,	P =   15.059 deg,	R =   90.598 deg
};
P[1013]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.997  mm,	Y =   71.905  mm,	Z =  362.323  mm,
	W = -178.184 deg,	P =   15.305 deg,	R =   90.479 deg
};
P[1014]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.036  mm,	Y =   71.748  mm,	Z =  362.444  mm,
	W = -178.677 deg,	P =   15.355 deg,	R =   90.350 deg
};
P[1015]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.072  mm,	Y =   71.596  mm,	Z =  362.540  mm,
	W = -179.155 deg,	P =   15.382 deg,	R =   90.224 deg
};
P[1016]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.109  mm,	Y =   71.441  mm,	Z =  362.613  mm,
	W = -179.652 deg,	P =   15.386 deg,	R =   90.092 deg
};
P[1017]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.145  mm,	Y =   71.290  mm,	Z =  362.660  mm,
	W =  179.865 deg,	P =   15.374 deg,	R =   89.964 deg
};
P[1018]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.182  mm,	Y =   71.137  mm,	Z =  362.682  mm,
	W =  179.362 deg,	P =   15.330 deg,	R =   89.831 deg
};
P[1019]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.218  mm,	Y =   70.986  mm,	Z =  362.679  mm,
	W =  178.861 deg,	P =   15.270 deg,	R =   89.700 deg
};
P[1020]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.254  mm,	Y =   70.835  mm,	Z =  362.651  mm,
	W =  178.370 deg,	P =   15.189 deg,	R =   89.573 deg
};
P[1021]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.325  mm,	Y =   70.377  mm,	Z =  362.682  mm,
	W =  177.853 deg,	P =   15.044 deg,	R =   89.442 deg
};
P[1022]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.670  mm,	Y =   67.984  mm,	Z =  363.253  mm,
	W =  177.505 deg,	P =   14.657 deg,	R =   89.368 deg
};
P[1023]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.012  mm,	Y =   65.599  mm,	Z =  363.791  mm,
	W =  177.134 deg,	P =   14.095 deg,	R =   89.302 deg
};
P[1024]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.355  mm,	Y =   63.208  mm,	Z =  364.294  mm,
	W =  176.745 deg,	P =   13.515 deg,	R =   89.239 deg
};
P[1025]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.691  mm,	Y =   60.824  mm,	Z =  364.756  mm,
	W =  176.354 deg,	P =   12.789 deg,	R =   89.192 deg
};
P[1026]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.086  mm,	Y =   58.399  mm,	Z =  365.187  mm,
	W =  175.961 deg,	P =   12.027 deg,	R =   89.157 deg
};
P[1027]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.181  mm,	Y =   55.529  mm,	Z =  365.783  mm,
	W =  175.884 deg,	P =   11.055 deg,	R =   89.209 deg
};
P[1028]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.265  mm,	Y =   52.652  mm,	Z =  366.328  mm,
	W =  175.813 deg,	P =   10.044 deg,	R =   89.269 deg
};
P[1029]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.366  mm,	Y =   49.776  mm,	Z =  366.817  mm,
	W =  175.768 deg,	P =    8.872 deg,	R =   89.346 deg
};
P[1030]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.482  mm,	Y =   46.895  mm,	Z =  367.247  mm,
	W =  175.736 deg,	P =    7.659 deg,	R =   89.431 deg
};
P[1031]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.603  mm,	Y =   44.011  mm,	Z =  367.613  mm,
	W =  175.722 deg,	P =    6.376 deg,	R =   89.524 deg
};
P[1032]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.747  mm,	Y =   41.124  mm,	Z =  367.914  mm,
	W =  175.728 deg,	P =    5.024 deg,	R =   89.625 deg
};
P[1033]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  459.899  mm,	Y =   38.232  mm,	Z =  368.146  mm,
	W =  175.751 deg,	P =    3.678 deg,	R =   89.727 deg
};
P[1034]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.063  mm,	Y =   35.340  mm,	Z =  368.309  mm,
	W =  175.791 deg,	P =    2.268 deg,	R =   89.833 deg
};
P[1035]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.239  mm,	Y =   32.443  mm,	Z =  368.403  mm,
	W =  175.853 deg,	P =    0.883 deg,	R =   89.936 deg
};
P[1036]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.430  mm,	Y =   29.544  mm,	Z =  368.427  mm,
	W =  175.930 deg,	P =   -0.456 deg,	R =   90.032 deg
};
P[1037]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.630  mm,	Y =   26.643  mm,	Z =  368.384  mm,
	W =  176.022 deg,	P =   -1.773 deg,	R =   90.123 deg
};
P[1038]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  460.844  mm,	Y =   23.740  mm,	Z =  368.277  mm,
	W =  176.130 deg,	P =   -3.014 deg,	R =   90.204 deg
};
P[1039]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.069  mm,	Y =   20.836  mm,	Z =  368.107  mm,
	W =  176.251 deg,	P =   -4.177 deg,	R =   90.273 deg
};
P[1040]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.297  mm,	Y =   17.931  mm,	Z =  367.881  mm,
	W =  176.385 deg,	P =   -5.284 deg,	R =   90.333 deg
};
P[1041]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.533  mm,	Y =   15.020  mm,	Z =  367.601  mm,
	W =  176.526 deg,	P =   -6.213 deg,	R =   90.376 deg
};
P[1042]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.756  mm,	Y =   12.108  mm,	Z =  367.273  mm,
	W =  176.675 deg,	P =   -7.075 deg,	R =   90.410 deg
};
P[1043]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  461.988  mm,	Y =    9.191  mm,	Z =  366.904  mm,
	W =  176.831 deg,	P =   -7.795 deg,	R =   90.430 deg
};
P[1044]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.222  mm,	Y =    6.269  mm,	Z =  366.499  mm,
	W =  176.990 deg,	P =   -8.374 deg,	R =   90.439 deg
};
P[1045]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.463  mm,	Y =    3.346  mm,	Z =  366.067  mm,
	W =  177.147 deg,	P =   -8.866 deg,	R =   90.440 deg
};
P[1046]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.709  mm,	Y =    0.411  mm,	Z =  365.612  mm,
	W =  177.312 deg,	P =   -9.143 deg,	R =   90.427 deg
};
P[1047]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  462.951  mm,	Y =   -2.526  mm,	Z =  365.142  mm,
	W =  177.459 deg,	P =   -9.361 deg,	R =   90.414 deg
};
P[1048]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  463.189  mm,	Y =   -5.477  mm,	Z =  364.665  mm,
	W =  177.618 deg,	P =   -9.373 deg,	R =   90.388 deg
};
P[1049]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  463.422  mm,	Y =   -8.435  mm,	Z =  364.186  mm,
	W =  177.765 deg,	P =   -9.280 deg,	R =   90.361 deg
};
P[1050]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  463.651  mm,	Y =  -11.402  mm,	Z =  363.714  mm,
	W =  177.899 deg,	P =   -9.082 deg,	R =   90.332 deg
};
P[1051]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  463.870  mm,	Y =  -14.384  mm,	Z =  363.254  mm,
	W =  178.025 deg,	P =   -8.709 deg,	R =   90.299 deg
};
P[1052]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.086  mm,	Y =  -17.373  mm,	Z =  362.813  mm,
	W =  178.142 deg,	P =   -8.285 deg,	R =   90.268 deg
};
P[1053]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.291  mm,	Y =  -20.379  mm,	Z =  362.398  mm,
	W =  178.243 deg,	P =   -7.690 deg,	R =   90.235 deg
};
P[1054]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.489  mm,	Y =  -23.393  mm,	Z =  362.013  mm,
	W =  178.334 deg,	P =   -7.036 deg,	R =   90.204 deg
};
P[1055]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.681  mm,	Y =  -26.418  mm,	Z =  361.664  mm,
	W =  178.410 deg,	P =   -6.302 deg,	R =   90.175 deg
};
P[1056]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  464.862  mm,	Y =  -29.454  mm,	Z =  361.355  mm,
	W =  178.473 deg,	P =   -5.476 deg,	R =   90.146 deg
};
P[1057]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.039  mm,	Y =  -32.495  mm,	Z =  361.090  mm,
	W =  178.521 deg,	P =   -4.647 deg,	R =   90.120 deg
};
P[1058]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.204  mm,	Y =  -35.547  mm,	Z =  360.871  mm,
	W =  178.555 deg,	P =   -3.725 deg,	R =   90.094 deg
};
P[1059]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.363  mm,	Y =  -38.602  mm,	Z =  360.700  mm,
	W =  178.571 deg,	P =   -2.815 deg,	R =   90.070 deg
};
P[1060]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.513  mm,	Y =  -41.658  mm,	Z =  360.577  mm,
	W =  178.575 deg,	P =   -1.924 deg,	R =   90.048 deg
};
P[1061]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.656  mm,	Y =  -44.715  mm,	Z =  360.502  mm,
	W =  178.566 deg,	P =   -1.036 deg,	R =   90.026 deg
};
P[1062]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.788  mm,	Y =  -47.770  mm,	Z =  360.473  mm,
	W =  178.543 deg,	P =   -0.205 deg,	R =   90.005 deg
};
P[1063]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  465.917  mm,	Y =  -50.822  mm,	Z =  360.487  mm,
	W =  178.511 deg,	P =    0.572 deg,	R =   89.985 deg
};
P[1064]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  466.030  mm,	Y =  -53.870  mm,	Z =  360.539  mm,
	W =  178.462 deg,	P =    1.299 deg,	R =   89.965 deg
};
P[1065]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  466.139  mm,	Y =  -56.908  mm,	Z =  360.627  mm,
	W =  178.410 deg,	P =    1.879 deg,	R =   89.948 deg
};
P[1066]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  466.241  mm,	Y =  -59.939  mm,	Z =  360.744  mm,
	W =  178.343 deg,	P =    2.388 deg,	R =   89.931 deg
};
P[1067]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  467.655  mm,	Y =  -62.603  mm,	Z =  360.903  mm,
	W =  178.444 deg,	P =    2.764 deg,	R =   89.925 deg
};
P[1068]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  470.326  mm,	Y =  -63.936  mm,	Z =  361.036  mm,
	W =  178.758 deg,	P =    2.998 deg,	R =   89.935 deg
};
P[1069]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.295  mm,	Y =  -63.786  mm,	Z =  361.082  mm,
	W =  179.141 deg,	P =    3.050 deg,	R =   89.954 deg
};
P[1070]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.264  mm,	Y =  -63.632  mm,	Z =  361.108  mm,
	W =  179.524 deg,	P =    3.047 deg,	R =   89.975 deg
};
P[1071]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.233  mm,	Y =  -63.474  mm,	Z =  361.115  mm,
	W =  179.902 deg,	P =    3.036 deg,	R =   89.995 deg
};
P[1072]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.203  mm,	Y =  -63.311  mm,	Z =  361.101  mm,
	W = -179.727 deg,	P =    3.011 deg,	R =   90.014 deg
};
P[1073]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.172  mm,	Y =  -63.143  mm,	Z =  361.069  mm,
	W = -179.343 deg,	P =    2.967 deg,	R =   90.034 deg
};
P[1074]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.141  mm,	Y =  -62.969  mm,	Z =  361.016  mm,
	W = -178.973 deg,	P =    2.901 deg,	R =   90.052 deg
};
P[1075]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.910  mm,	Y =  -61.864  mm,	Z =  360.904  mm,
	W = -178.642 deg,	P =    2.701 deg,	R =   90.064 deg
};
P[1076]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.890  mm,	Y =  -58.840  mm,	Z =  360.772  mm,
	W = -178.711 deg,	P =    2.314 deg,	R =   90.052 deg
};
P[1077]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.870  mm,	Y =  -55.801  mm,	Z =  360.665  mm,
	W = -178.769 deg,	P =    1.726 deg,	R =   90.037 deg
};
P[1078]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.849  mm,	Y =  -52.758  mm,	Z =  360.590  mm,
	W = -178.822 deg,	P =    1.091 deg,	R =   90.022 deg
};
P[1079]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.762  mm,	Y =  -49.708  mm,	Z =  360.553  mm,
	W = -178.873 deg,	P =    0.351 deg,	R =   90.007 deg
};
P[1080]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.613  mm,	Y =  -46.654  mm,	Z =  360.559  mm,
	W = -178.922 deg,	P =   -0.468 deg,	R =   89.991 deg
};
P[1081]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.470  mm,	Y =  -43.599  mm,	Z =  360.609  mm,
	W = -178.961 deg,	P =   -1.310 deg,	R =   89.976 deg
};
P[1082]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.341  mm,	Y =  -40.539  mm,	Z =  360.706  mm,
	W = -178.987 deg,	P =   -2.236 deg,	R =   89.960 deg
};
P[1083]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.218  mm,	Y =  -37.480  mm,	Z =  360.852  mm,
	W = -179.006 deg,	P =   -3.165 deg,	R =   89.945 deg
};
P[1084]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  490.104  mm,	Y =  -34.425  mm,	Z =  361.047  mm,
	W = -179.011 deg,	P =   -4.075 deg,	R =   89.930 deg
};
P[1085]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.996  mm,	Y =  -31.373  mm,	Z =  361.291  mm,
	W = -179.010 deg,	P =   -4.989 deg,	R =   89.914 deg
};
P[1086]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.902  mm,	Y =  -28.329  mm,	Z =  361.582  mm,
	W = -178.995 deg,	P =   -5.844 deg,	R =   89.898 deg
};
P[1087]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.809  mm,	Y =  -25.292  mm,	Z =  361.917  mm,
	W = -178.977 deg,	P =   -6.656 deg,	R =   89.881 deg
};
P[1088]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.732  mm,	Y =  -22.262  mm,	Z =  362.292  mm,
	W = -178.944 deg,	P =   -7.426 deg,	R =   89.863 deg
};
P[1089]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.660  mm,	Y =  -19.248  mm,	Z =  362.703  mm,
	W = -178.911 deg,	P =   -8.041 deg,	R =   89.848 deg
};
P[1090]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.597  mm,	Y =  -16.241  mm,	Z =  363.145  mm,
	W = -178.864 deg,	P =   -8.609 deg,	R =   89.830 deg
};
P[1091]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.544  mm,	Y =  -13.248  mm,	Z =  363.611  mm,
	W = -178.816 deg,	P =   -9.040 deg,	R =   89.814 deg
};
P[1092]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.501  mm,	Y =  -10.265  mm,	Z =  364.097  mm,
	W = -178.761 deg,	P =   -9.355 deg,	R =   89.798 deg
};
P[1093]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.462  mm,	Y =   -7.291  mm,	Z =  364.594  mm,
	W = -178.700 deg,	P =   -9.575 deg,	R =   89.784 deg
};
P[1094]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.430  mm,	Y =   -4.332  mm,	Z =  365.095  mm,
	W = -178.642 deg,	P =   -9.601 deg,	R =   89.774 deg
};
P[1095]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.403  mm,	Y =   -1.377  mm,	Z =  365.596  mm,
	W = -178.576 deg,	P =   -9.555 deg,	R =   89.764 deg
};
P[1096]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.379  mm,	Y =    1.565  mm,	Z =  366.085  mm,
	W = -178.519 deg,	P =   -9.310 deg,	R =   89.760 deg
};
P[1097]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.359  mm,	Y =    4.502  mm,	Z =  366.560  mm,
	W = -178.451 deg,	P =   -8.948 deg,	R =   89.759 deg
};
P[1098]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.339  mm,	Y =    7.434  mm,	Z =  367.009  mm,
	W = -178.392 deg,	P =   -8.462 deg,	R =   89.763 deg
};
P[1099]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.316  mm,	Y =   10.357  mm,	Z =  367.429  mm,
	W = -178.334 deg,	P =   -7.787 deg,	R =   89.774 deg
};
P[1100]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.286  mm,	Y =   13.280  mm,	Z =  367.811  mm,
	W = -178.280 deg,	P =   -7.046 deg,	R =   89.789 deg
};
P[1101]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.258  mm,	Y =   16.194  mm,	Z =  368.148  mm,
	W = -178.235 deg,	P =   -6.099 deg,	R =   89.812 deg
};
P[1102]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.226  mm,	Y =   19.109  mm,	Z =  368.436  mm,
	W = -178.193 deg,	P =   -5.080 deg,	R =   89.840 deg
};
P[1103]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.185  mm,	Y =   22.021  mm,	Z =  368.667  mm,
	W = -178.163 deg,	P =   -3.950 deg,	R =   89.873 deg
};
P[1104]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.134  mm,	Y =   24.928  mm,	Z =  368.839  mm,
	W = -178.134 deg,	P =   -2.696 deg,	R =   89.912 deg
};
P[1105]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  489.071  mm,	Y =   27.836  mm,	Z =  368.945  mm,
	W = -178.119 deg,	P =   -1.420 deg,	R =   89.953 deg
};
P[1106]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.997  mm,	Y =   30.736  mm,	Z =  368.983  mm,
	W = -178.110 deg,	P =   -0.008 deg,	R =   90.000 deg
};
P[1107]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.908  mm,	Y =   33.635  mm,	Z =  368.951  mm,
	W = -178.115 deg,	P =    1.412 deg,	R =   90.046 deg
};
P[1108]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.804  mm,	Y =   36.532  mm,	Z =  368.847  mm,
	W = -178.125 deg,	P =    2.844 deg,	R =   90.093 deg
};
P[1109]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.687  mm,	Y =   39.423  mm,	Z =  368.671  mm,
	W = -178.153 deg,	P =    4.288 deg,	R =   90.138 deg
};
P[1110]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.556  mm,	Y =   42.311  mm,	Z =  368.422  mm,
	W = -178.187 deg,	P =    5.696 deg,	R =   90.180 deg
};
P[1111]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.414  mm,	Y =   45.194  mm,	Z =  368.103  mm,
	W = -178.228 deg,	P =    7.076 deg,	R =   90.218 deg
};
P[1112]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  488.255  mm,	Y =   48.069  mm,	Z =  367.716  mm,
	W = -178.281 deg,	P =    8.420 deg,	R =   90.252 deg
};
P[1113]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  487.388  mm,	Y =   50.825  mm,	Z =  367.303  mm,
	W = -178.488 deg,	P =    9.589 deg,	R =   90.252 deg
};
P[1114]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  485.120  mm,	Y =   52.672  mm,	Z =  367.028  mm,
	W = -178.960 deg,	P =   10.414 deg,	R =   90.188 deg
};
P[1115]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.856  mm,	Y =   54.528  mm,	Z =  366.706  mm,
	W = -179.428 deg,	P =   11.106 deg,	R =   90.110 deg
};
P[1116]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.378  mm,	Y =   56.099  mm,	Z =  366.403  mm,
	W = -179.923 deg,	P =   11.687 deg,	R =   90.016 deg
};
P[1117]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.642  mm,	Y =   55.005  mm,	Z =  366.616  mm,
	W =  179.525 deg,	P =   11.283 deg,	R =   89.907 deg
};
P[1118]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.820  mm,	Y =   52.737  mm,	Z =  367.031  mm,
	W =  179.151 deg,	P =   10.450 deg,	R =   89.846 deg
};
P[1119]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.993  mm,	Y =   50.476  mm,	Z =  367.395  mm,
	W =  178.766 deg,	P =    9.455 deg,	R =   89.797 deg
};
P[1120]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.204  mm,	Y =   47.700  mm,	Z =  367.810  mm,
	W =  178.583 deg,	P =    8.259 deg,	R =   89.796 deg
};
P[1121]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.279  mm,	Y =   44.820  mm,	Z =  368.195  mm,
	W =  178.585 deg,	P =    6.914 deg,	R =   89.830 deg
};
P[1122]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.374  mm,	Y =   41.936  mm,	Z =  368.513  mm,
	W =  178.597 deg,	P =    5.526 deg,	R =   89.865 deg
};
P[1123]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.479  mm,	Y =   39.047  mm,	Z =  368.759  mm,
	W =  178.615 deg,	P =    4.109 deg,	R =   89.901 deg
};
P[1124]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.599  mm,	Y =   36.157  mm,	Z =  368.933  mm,
	W =  178.642 deg,	P =    2.653 deg,	R =   89.937 deg
};
P[1125]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.731  mm,	Y =   33.261  mm,	Z =  369.034  mm,
	W =  178.675 deg,	P =    1.221 deg,	R =   89.972 deg
};
P[1126]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  473.880  mm,	Y =   30.365  mm,	Z =  369.062  mm,
	W =  178.718 deg,	P =   -0.204 deg,	R =   90.005 deg
};
P[1127]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.039  mm,	Y =   27.467  mm,	Z =  369.020  mm,
	W =  178.764 deg,	P =   -1.604 deg,	R =   90.035 deg
};
P[1128]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.214  mm,	Y =   24.565  mm,	Z =  368.910  mm,
	W =  178.820 deg,	P =   -2.891 deg,	R =   90.060 deg
};
P[1129]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.401  mm,	Y =   21.663  mm,	Z =  368.734  mm,
	W =  178.875 deg,	P =   -4.133 deg,	R =   90.081 deg
};
P[1130]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.592  mm,	Y =   18.758  mm,	Z =  368.499  mm,
	W =  178.942 deg,	P =   -5.268 deg,	R =   90.097 deg
};
P[1131]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.800  mm,	Y =   15.850  mm,	Z =  368.208  mm,
	W =  179.003 deg,	P =   -6.277 deg,	R =   90.109 deg
};
P[1132]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  474.987  mm,	Y =   12.942  mm,	Z =  367.867  mm,
	W =  179.074 deg,	P =   -7.217 deg,	R =   90.116 deg
};
P[1133]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.189  mm,	Y =   10.025  mm,	Z =  367.481  mm,
	W =  179.136 deg,	P =   -7.947 deg,	R =   90.120 deg
};
P[1134]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.388  mm,	Y =    7.108  mm,	Z =  367.059  mm,
	W =  179.205 deg,	P =   -8.594 deg,	R =   90.119 deg
};
P[1135]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.595  mm,	Y =    4.185  mm,	Z =  366.607  mm,
	W =  179.268 deg,	P =   -9.089 deg,	R =   90.116 deg
};
P[1136]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  475.811  mm,	Y =    1.255  mm,	Z =  366.130  mm,
	W =  179.336 deg,	P =   -9.420 deg,	R =   90.109 deg
};
P[1137]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.020  mm,	Y =   -1.679  mm,	Z =  365.639  mm,
	W =  179.398 deg,	P =   -9.675 deg,	R =   90.101 deg
};
P[1138]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.228  mm,	Y =   -4.628  mm,	Z =  365.138  mm,
	W =  179.458 deg,	P =   -9.690 deg,	R =   90.091 deg
};
P[1139]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.431  mm,	Y =   -7.582  mm,	Z =  364.635  mm,
	W =  179.512 deg,	P =   -9.641 deg,	R =   90.082 deg
};
P[1140]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.628  mm,	Y =  -10.550  mm,	Z =  364.138  mm,
	W =  179.566 deg,	P =   -9.418 deg,	R =   90.071 deg
};
P[1141]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.817  mm,	Y =  -13.528  mm,	Z =  363.653  mm,
	W =  179.609 deg,	P =   -9.080 deg,	R =   90.062 deg
};
P[1142]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  476.999  mm,	Y =  -16.517  mm,	Z =  363.188  mm,
	W =  179.656 deg,	P =   -8.644 deg,	R =   90.052 deg
};
P[1143]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.173  mm,	Y =  -19.521  mm,	Z =  362.748  mm,
	W =  179.687 deg,	P =   -8.052 deg,	R =   90.044 deg
};
P[1144]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.339  mm,	Y =  -22.534  mm,	Z =  362.339  mm,
	W =  179.714 deg,	P =   -7.405 deg,	R =   90.037 deg
};
P[1145]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.496  mm,	Y =  -25.560  mm,	Z =  361.967  mm,
	W =  179.739 deg,	P =   -6.637 deg,	R =   90.030 deg
};
P[1146]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.644  mm,	Y =  -28.596  mm,	Z =  361.636  mm,
	W =  179.762 deg,	P =   -5.810 deg,	R =   90.024 deg
};
P[1147]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.785  mm,	Y =  -31.640  mm,	Z =  361.350  mm,
	W =  179.780 deg,	P =   -4.939 deg,	R =   90.019 deg
};
P[1148]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.915  mm,	Y =  -34.693  mm,	Z =  361.111  mm,
	W =  179.794 deg,	P =   -4.009 deg,	R =   90.014 deg
};
P[1149]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.037  mm,	Y =  -37.749  mm,	Z =  360.922  mm,
	W =  179.808 deg,	P =   -3.085 deg,	R =   90.010 deg
};
P[1150]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.150  mm,	Y =  -40.810  mm,	Z =  360.784  mm,
	W =  179.817 deg,	P =   -2.137 deg,	R =   90.007 deg
};
P[1151]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.254  mm,	Y =  -43.873  mm,	Z =  360.695  mm,
	W =  179.828 deg,	P =   -1.199 deg,	R =   90.004 deg
};
P[1152]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.349  mm,	Y =  -46.931  mm,	Z =  360.654  mm,
	W =  179.831 deg,	P =   -0.341 deg,	R =   90.001 deg
};
P[1153]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.435  mm,	Y =  -49.987  mm,	Z =  360.659  mm,
	W =  179.833 deg,	P =    0.485 deg,	R =   89.999 deg
};
P[1154]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.959  mm,	Y =  -52.610  mm,	Z =  360.698  mm,
	W =  179.997 deg,	P =    1.134 deg,	R =   90.000 deg
};
P[1155]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.887  mm,	Y =  -49.710  mm,	Z =  360.658  mm,
	W = -179.906 deg,	P =    0.418 deg,	R =   90.001 deg
};
P[1156]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.855  mm,	Y =  -46.651  mm,	Z =  360.657  mm,
	W = -179.911 deg,	P =   -0.419 deg,	R =   89.999 deg
};
P[1157]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.828  mm,	Y =  -43.591  mm,	Z =  360.703  mm,
	W = -179.917 deg,	P =   -1.282 deg,	R =   89.998 deg
};
P[1158]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.816  mm,	Y =  -40.527  mm,	Z =  360.797  mm,
	W = -179.918 deg,	P =   -2.221 deg,	R =   89.997 deg
};
P[1159]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.810  mm,	Y =  -37.464  mm,	Z =  360.941  mm,
	W = -179.921 deg,	P =   -3.173 deg,	R =   89.996 deg
};
P[1160]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.813  mm,	Y =  -34.406  mm,	Z =  361.135  mm,
	W = -179.919 deg,	P =   -4.095 deg,	R =   89.994 deg
};
P[1161]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.824  mm,	Y =  -31.351  mm,	Z =  361.379  mm,
	W = -179.920 deg,	P =   -5.026 deg,	R =   89.993 deg
};
P[1162]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.847  mm,	Y =  -28.304  mm,	Z =  361.670  mm,
	W = -179.914 deg,	P =   -5.895 deg,	R =   89.991 deg
};
P[1163]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.872  mm,	Y =  -25.266  mm,	Z =  362.007  mm,
	W = -179.908 deg,	P =   -6.714 deg,	R =   89.989 deg
};
P[1164]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.914  mm,	Y =  -22.234  mm,	Z =  362.384  mm,
	W = -179.901 deg,	P =   -7.502 deg,	R =   89.987 deg
};
P[1165]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  480.961  mm,	Y =  -19.220  mm,	Z =  362.797  mm,
	W = -179.891 deg,	P =   -8.118 deg,	R =   89.985 deg
};
P[1166]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.017  mm,	Y =  -16.213  mm,	Z =  363.243  mm,
	W = -179.883 deg,	P =   -8.702 deg,	R =   89.982 deg
};
P[1167]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.083  mm,	Y =  -13.220  mm,	Z =  363.712  mm,
	W = -179.865 deg,	P =   -9.133 deg,	R =   89.979 deg
};
P[1168]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.158  mm,	Y =  -10.238  mm,	Z =  364.201  mm,
	W = -179.848 deg,	P =   -9.452 deg,	R =   89.975 deg
};
P[1169]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.239  mm,	Y =   -7.266  mm,	Z =  364.702  mm,
	W = -179.829 deg,	P =   -9.678 deg,	R =   89.971 deg
};
P[1170]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.326  mm,	Y =   -4.308  mm,	Z =  365.208  mm,
	W = -179.808 deg,	P =   -9.704 deg,	R =   89.968 deg
};
P[1171]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.418  mm,	Y =   -1.355  mm,	Z =  365.712  mm,
	W = -179.788 deg,	P =   -9.668 deg,	R =   89.964 deg
};
P[1172]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.513  mm,	Y =    1.585  mm,	Z =  366.206  mm,
	W = -179.759 deg,	P =   -9.411 deg,	R =   89.961 deg
};
P[1173]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.613  mm,	Y =    4.519  mm,	Z =  366.684  mm,
	W = -179.730 deg,	P =   -9.051 deg,	R =   89.958 deg
};
P[1174]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.713  mm,	Y =    7.448  mm,	Z =  367.137  mm,
	W = -179.704 deg,	P =   -8.558 deg,	R =   89.956 deg
};
P[1175]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.809  mm,	Y =   10.369  mm,	Z =  367.560  mm,
	W = -179.673 deg,	P =   -7.883 deg,	R =   89.955 deg
};
P[1176]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.900  mm,	Y =   13.291  mm,	Z =  367.945  mm,
	W = -179.649 deg,	P =   -7.143 deg,	R =   89.956 deg
};
P[1177]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.990  mm,	Y =   16.202  mm,	Z =  368.284  mm,
	W = -179.618 deg,	P =   -6.183 deg,	R =   89.959 deg
};
P[1178]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.078  mm,	Y =   19.115  mm,	Z =  368.574  mm,
	W = -179.589 deg,	P =   -5.154 deg,	R =   89.963 deg
};
P[1179]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.157  mm,	Y =   22.025  mm,	Z =  368.807  mm,
	W = -179.567 deg,	P =   -4.009 deg,	R =   89.970 deg
};
P[1180]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.226  mm,	Y =   24.931  mm,	Z =  368.979  mm,
	W = -179.544 deg,	P =   -2.749 deg,	R =   89.978 deg
};
P[1181]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.283  mm,	Y =   27.838  mm,	Z =  369.085  mm,
	W = -179.527 deg,	P =   -1.452 deg,	R =   89.988 deg
};
P[1182]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.327  mm,	Y =   30.738  mm,	Z =  369.122  mm,
	W = -179.512 deg,	P =   -0.036 deg,	R =   90.000 deg
};
P[1183]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.357  mm,	Y =   33.638  mm,	Z =  369.088  mm,
	W = -179.504 deg,	P =    1.399 deg,	R =   90.012 deg
};
P[1184]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.370  mm,	Y =   36.535  mm,	Z =  368.980  mm,
	W = -179.498 deg,	P =    2.842 deg,	R =   90.025 deg
};
P[1185]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.370  mm,	Y =   39.427  mm,	Z =  368.800  mm,
	W = -179.501 deg,	P =    4.301 deg,	R =   90.037 deg
};
P[1186]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.356  mm,	Y =   42.317  mm,	Z =  368.546  mm,
	W = -179.502 deg,	P =    5.726 deg,	R =   90.050 deg
};
P[1187]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.330  mm,	Y =   45.202  mm,	Z =  368.221  mm,
	W = -179.515 deg,	P =    7.112 deg,	R =   90.060 deg
};
P[1188]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  482.286  mm,	Y =   48.080  mm,	Z =  367.828  mm,
	W = -179.534 deg,	P =    8.466 deg,	R =   90.069 deg
};
P[1189]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  481.270  mm,	Y =   50.785  mm,	Z =  367.404  mm,
	W = -179.740 deg,	P =    9.613 deg,	R =   90.043 deg
};
P[1190]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.313  mm,	Y =   50.682  mm,	Z =  367.419  mm,
	W =  179.653 deg,	P =    9.569 deg,	R =   89.942 deg
};
P[1191]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.713  mm,	Y =   47.862  mm,	Z =  367.860  mm,
	W =  179.524 deg,	P =    8.374 deg,	R =   89.931 deg
};
P[1192]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.670  mm,	Y =   44.984  mm,	Z =  368.248  mm,
	W =  179.509 deg,	P =    7.010 deg,	R =   89.940 deg
};
P[1193]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.644  mm,	Y =   42.099  mm,	Z =  368.568  mm,
	W =  179.502 deg,	P =    5.619 deg,	R =   89.951 deg
};
P[1194]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.631  mm,	Y =   39.209  mm,	Z =  368.816  mm,
	W =  179.498 deg,	P =    4.194 deg,	R =   89.963 deg
};
P[1195]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.633  mm,	Y =   36.316  mm,	Z =  368.991  mm,
	W =  179.501 deg,	P =    2.733 deg,	R =   89.976 deg
};
P[1196]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.647  mm,	Y =   33.419  mm,	Z =  369.093  mm,
	W =  179.504 deg,	P =    1.290 deg,	R =   89.989 deg
};
P[1197]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.677  mm,	Y =   30.519  mm,	Z =  369.122  mm,
	W =  179.517 deg,	P =   -0.142 deg,	R =   90.001 deg
};
P[1198]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.718  mm,	Y =   27.618  mm,	Z =  369.079  mm,
	W =  179.535 deg,	P =   -1.550 deg,	R =   90.013 deg
};
P[1199]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.777  mm,	Y =   24.711  mm,	Z =  368.968  mm,
	W =  179.550 deg,	P =   -2.847 deg,	R =   90.022 deg
};
P[1200]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.846  mm,	Y =   21.805  mm,	Z =  368.791  mm,
	W =  179.577 deg,	P =   -4.095 deg,	R =   90.030 deg
};
P[1201]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  477.923  mm,	Y =   18.895  mm,	Z =  368.554  mm,
	W =  179.595 deg,	P =   -5.239 deg,	R =   90.037 deg
};
P[1202]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.015  mm,	Y =   15.982  mm,	Z =  368.260  mm,
	W =  179.627 deg,	P =   -6.255 deg,	R =   90.041 deg
};
P[1203]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.088  mm,	Y =   13.071  mm,	Z =  367.917  mm,
	W =  179.646 deg,	P =   -7.220 deg,	R =   90.045 deg
};
P[1204]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.175  mm,	Y =   10.148  mm,	Z =  367.529  mm,
	W =  179.677 deg,	P =   -7.938 deg,	R =   90.045 deg
};
P[1205]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.259  mm,	Y =    7.226  mm,	Z =  367.103  mm,
	W =  179.706 deg,	P =   -8.595 deg,	R =   90.044 deg
};
P[1206]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.352  mm,	Y =    4.297  mm,	Z =  366.648  mm,
	W =  179.729 deg,	P =   -9.087 deg,	R =   90.043 deg
};
P[1207]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.453  mm,	Y =    1.362  mm,	Z =  366.168  mm,
	W =  179.757 deg,	P =   -9.430 deg,	R =   90.040 deg
};
P[1208]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.549  mm,	Y =   -1.578  mm,	Z =  365.674  mm,
	W =  179.781 deg,	P =   -9.678 deg,	R =   90.037 deg
};
P[1209]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.644  mm,	Y =   -4.532  mm,	Z =  365.169  mm,
	W =  179.805 deg,	P =   -9.705 deg,	R =   90.033 deg
};
P[1210]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.733  mm,	Y =   -7.490  mm,	Z =  364.664  mm,
	W =  179.823 deg,	P =   -9.667 deg,	R =   90.030 deg
};
P[1211]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.816  mm,	Y =  -10.464  mm,	Z =  364.164  mm,
	W =  179.845 deg,	P =   -9.436 deg,	R =   90.025 deg
};
P[1212]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.892  mm,	Y =  -13.446  mm,	Z =  363.676  mm,
	W =  179.856 deg,	P =   -9.104 deg,	R =   90.023 deg
};
P[1213]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  478.960  mm,	Y =  -16.440  mm,	Z =  363.208  mm,
	W =  179.876 deg,	P =   -8.663 deg,	R =   90.019 deg
};
P[1214]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.019  mm,	Y =  -19.448  mm,	Z =  362.765  mm,
	W =  179.887 deg,	P =   -8.072 deg,	R =   90.016 deg
};
P[1215]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.070  mm,	Y =  -22.465  mm,	Z =  362.354  mm,
	W =  179.899 deg,	P =   -7.426 deg,	R =   90.013 deg
};
P[1216]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.113  mm,	Y =  -25.495  mm,	Z =  361.980  mm,
	W =  179.905 deg,	P =   -6.657 deg,	R =   90.011 deg
};
P[1217]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.144  mm,	Y =  -28.535  mm,	Z =  361.646  mm,
	W =  179.912 deg,	P =   -5.829 deg,	R =   90.009 deg
};
P[1218]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.169  mm,	Y =  -31.484  mm,	Z =  361.367  mm,
	W =  179.916 deg,	P =   -4.986 deg,	R =   90.007 deg
};
P[1219]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.154  mm,	Y =  -32.411  mm,	Z =  371.993  mm,
	W =  179.916 deg,	P =   -4.986 deg,	R =   90.007 deg
};
P[1220]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.144  mm,	Y =  -32.990  mm,	Z =  378.635  mm,
	W =  179.916 deg,	P =   -4.986 deg,	R =   90.007 deg
};
P[1221]{
   GP1:
	UF : 0, UT : 1,		CONFIG : 'N U T, 0, 0, 0',
	X =  479.134  mm,	Y =  -33.570  mm,	Z =  385.276  mm,
	W =  179.916 deg,	P =   -4.986 deg,	R =   90.007 deg
};
/END
