MODULE demo
    CONST jointtarget home:=[[0.0000, -30.0000, 60.0000, 0.0000, 45.0000, 0.0000],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget approach:=[[500.000,100.000,400.000],[0.000000,0.707107,0.707107,0.000000],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick:=[[500.000,-200.000,300.000],[0.113441,0.913955,0.386794,-0.046989],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget leave:=[[10.0000, -20.0000, 50.0000, 5.0000, 40.0000, -5.0000],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        MoveAbsJ home, [3500.0,500,5000,1000], fine, tool0;
        MoveL approach, [250.0,500,5000,1000], z10, tool0;
        MoveL pick, [100.0,500,5000,1000], fine, tool0;
        MoveAbsJ leave, [7000.0,500,5000,1000], [FALSE,25.0,37.5,37.5,3.75,37.5,3.75], tool0;
    ENDPROC
ENDMODULE
