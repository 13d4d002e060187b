MODULE pick_place
    ! pick_place: robot MZ07, written by workbench (ABB RAPID post)
    ! units: mm, deg, kg, s; orientations as quaternions [q1,q2,q3,q4] = [w,x,y,z]
    ! robtargets: TCP in the move's work object; confdata [cf1,cf4,cf6,cfx] by ABB's rules
    ! joint moves run in the planned time (\T); their v1000 is nominal

    PERS tooldata gripper:=[TRUE,[[0,0,150],[1,0,0,0]],[2,[0,0,60],[1,0,0,0],0,0,0]];
    CONST robtarget above_left:=[[430,180,580],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pick:=[[430,180,495],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget lift:=[[430,180,580],[0,1,0,0],[0,0,0,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget above_right:=[[430,-180,580],[0,1,0,0],[-1,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget place:=[[430,-180,535],[0,1,0,0],[-1,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget retract:=[[430,-180,580],[0,1,0,0],[-1,0,-1,1],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST jointtarget home:=[[0,90,0,0,-90,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        ! pick a part from the left fixture, place it on the right one
        MoveJ above_left, [250,45,5000,1000], fine, gripper\WObj:=wobj0;
        MoveL pick, [150,500,5000,1000], fine, gripper\WObj:=wobj0;
        ! gripper close
        SetDO grip, 1;
        WaitDI gripper_closed, 1\MaxTime:=2;
        WaitTime 0.2;
        MoveL lift, [250,500,5000,1000], z30, gripper\WObj:=wobj0;
        MoveL above_right, [400,500,5000,1000], z30, gripper\WObj:=wobj0;
        MoveL place, [150,500,5000,1000], fine, gripper\WObj:=wobj0;
        ! gripper open
        SetDO grip, 0;
        WaitDI gripper_opened, 1\MaxTime:=2;
        WaitTime 0.2;
        MoveL retract, [250,500,5000,1000], fine, gripper\WObj:=wobj0;
        MoveAbsJ home, v1000\T:=0.3127, fine, gripper\WObj:=wobj0;
    ENDPROC
ENDMODULE
