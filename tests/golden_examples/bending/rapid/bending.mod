MODULE bending
    ! bending: robot NACHI MZ07, written by workbench (ABB RAPID post)
    ! units: mm, deg, kg, s; orientations as quaternions [q1,q2,q3,q4] = [w,x,y,z]
    ! robtargets: TCP in the move's work object; confdata [cf1,cf4,cf6,cfx] by ABB's rules
    ! joint moves run in the planned time (\T); their v1000 is nominal

    PERS tooldata suction_gripper:=[TRUE,[[0,0,120],[1,0,0,0]],[2.5,[0,0,55],[1,0,0,0],0,0,0]];
    CONST robtarget b1_approach:=[[405.405421,0,411.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b1_bend:=[[555.405421,0,351.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b1_retreat:=[[405.405421,0,411.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b2_approach:=[[405.405421,0,411.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b2_bend:=[[555.405421,0,351.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b2_retreat:=[[405.405421,0,411.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b3_approach:=[[448.468474,0,411.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b3_bend:=[[598.468474,0,351.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b3_retreat:=[[448.468474,0,411.5],[0,0.707106781,-0.707106781,0],[0,0,1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b4_approach:=[[448.468474,0,411.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b4_bend:=[[598.468474,0,351.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b4_retreat:=[[448.468474,0,411.5],[0,0.707106781,0.707106781,0],[0,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b5_approach:=[[397.172567,0,411.5],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b5_bend:=[[547.172567,0,351.5],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b5_retreat:=[[397.172567,0,411.5],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b6_approach:=[[397.172567,0,411.5],[0,0,1,0],[0,0,2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b6_bend:=[[547.172567,0,351.5],[0,0,1,0],[0,0,2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget b6_retreat:=[[397.172567,0,411.5],[0,0,1,0],[0,0,2,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget transfer1:=[[420,-400,440],[0,1,0,0],[-1,0,3,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget transfer2:=[[150,-560,480],[0,1,0,0],[-1,0,3,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pallet:=[[0,-650,140.75],[0,1,0,0],[-1,0,3,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home:=[[0,90,0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ! bending: 6 bends (front/elbow up/flip)
        ! load: the plan has no blank station; the blank is put into the gripper here
        ! gripper close
        SetDO vacuum, 1;
        WaitDI vacuum_ok, 1\MaxTime:=2;
        WaitTime 0.3;
        ! bend 'b23' (step 1)
        MoveJ b1_approach, [250,45,5000,1000], fine, suction_gripper\WObj:=wobj0;
        MoveL b1_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b1_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! bend 'b45' (step 2)
        MoveJ b2_approach, v1000\T:=0.535, fine, suction_gripper\WObj:=wobj0;
        MoveL b2_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b2_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! bend 'b12' (step 3)
        MoveJ b3_approach, v1000\T:=0.535, fine, suction_gripper\WObj:=wobj0;
        MoveL b3_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b3_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! bend 'b14' (step 4)
        MoveJ b4_approach, v1000\T:=0.535, fine, suction_gripper\WObj:=wobj0;
        MoveL b4_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b4_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! bend 'b16' (step 5)
        MoveJ b5_approach, v1000\T:=0.355, fine, suction_gripper\WObj:=wobj0;
        MoveL b5_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b5_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! bend 'b17' (step 6)
        MoveJ b6_approach, v1000\T:=0.535, fine, suction_gripper\WObj:=wobj0;
        MoveL b6_bend, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        SetDO press_start, 1;
        WaitDI press_clamped, 1\MaxTime:=30;
        SetDO press_start, 0;
        WaitDI press_done, 1\MaxTime:=30;
        MoveL b6_retreat, [250,500,5000,1000], fine, suction_gripper\WObj:=wobj0;
        ! transfer to the pallet as planned (checked)
        MoveJ transfer1, v1000\T:=0.4227, z5, suction_gripper\WObj:=wobj0;
        MoveJ transfer2, v1000\T:=0.3189, z5, suction_gripper\WObj:=wobj0;
        MoveJ pallet, v1000\T:=0.3295, fine, suction_gripper\WObj:=wobj0;
        ! unload
        ! gripper open
        SetDO vacuum, 0;
        WaitTime 0.3;
        MoveAbsJ home, v1000\T:=0.715, fine, suction_gripper\WObj:=wobj0;
    ENDPROC
ENDMODULE
