Procedure Func(sel,dir: Integer; wo,dT,Tmax: Double);
{ Numerical Integration; Direct or Transition Matrix }
Var   t0,y0,v0,t1,y1,v1,y2           : Double;
      dv1,dy1,dv2,dy2,y11,v11,v12   : Double;
      woT,woT2,woT4                  : Double;
      i,k                             : Integer;
Begin
k:=Round(Tmax/0.025);
  { Cosine }
  t0:=0; y0:=1;
  MapP(t0,y0,p0,q0);
  For i:=1 to k Do
  Begin
    t1:=t0+0.025;
    y1:=coc(t1*wo);
    MapP(t1,y1,p1,q1);
    MakeSline(p0,q0,p1,q1,0,100);
    t0:=t1; y0:=y1; p0:=p1; q0:=q1;
  End;
woT :=wo*dT;
woT2:=Sqr(woT);
woT4:=Sqr(woT2);
k:=Round(Tmax/dT);
Case sel Of
1: Begin
  WrTxtWXY(3,blac,1,1,'Standard Euler');
  t0:=0; v0:=0; y0:=1;
  MapP(t0,y0,p0,q0); Mark (p0,q0,120,100);
  For i:=1 to k Do
  Begin
    t1:= t0+dT;
    If dir=+1 Then
    Begin { Direct Integration }
      v1:=v0-woT*y0;
      y1:=y0+woT*v0;
    End Else
    Begin { Transition matrix }
      v1:=      v0 - woT*y0;
      y1:= woT*v0 +      y0;
    End;
    MapP(t1,y1,p1,q1);
    MakeSline(p0,q0,p1,q1,120,100); Mark (p1,q1,120,100);
    t0:=t1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
  End;
End;
2: Begin
  WrTxtWXY(3,blac,1,1,'Damped Euler');
  t0:=0; v0:=0; y0:=1;
  D:=0.5*woT;
  MapP(t0,y0,p0,q0);
  Mark(p0,q0,120,100);
  For i:=1 to k Do
    Begin
      t1:= t0+dT;
      If dir=+1 Then
        Begin { Direct Integration }
          v1:= v0-woT*(y0+2*D*v0);
          y1:= y0+woT*v0;
        End Else
        Begin { Transition matrix }
          v1:= (1-woT2)*v0 - woT*y0;
          y1:= woT*v0 + y0;
        End;
      MapP(t1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      t0:=t1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
3: Begin
  WrTxtWXY(3,blac,1,1,'False Euler');
  t0:=0; v0:=0; y0:=1;
  MapP(t0,y0,p0,q0); Mark(p0,q0,120,100);
  For i:=1 to k Do
    Begin
      t1:= t0+dT;
      If dir=+1 Then
        Begin { Direct Integration }
          v1:= v0-woT*y0;
          y1:= y0+woT*v1;
        End Else
        Begin { Transition matrix }
          v1:= v0 - woT*y0;
          y1:= woT*v0 + (1-woT2)*y0;
        End;
      MapP(t1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      t0:=t1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
4: Begin
  WrTxtWXY(3,blac,1,1,'Verlet');
  t0:=0; y0:=1; y2:=1; { v0=0 }
  MapP(t0,y0,p0,q0); Mark (p0,q0,120,100);
  For i:=1 to k Do
    Begin
      t1:= t0+dT;
      y1:=2*y0-y2+Sqr(dT)*(-wo*wo*y0);
      MapP(t1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      t0:=t1; y2:=y0; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
5: Begin
  WrTxtWXY(3,blac,1,1,'Standard Heun');
  t0:=0; v0:=0; y0:=1;
  MapP(t0,y0,p0,q0); Mark(p0,q0,120,100);
  For i:=1 to k Do
    Begin
      t1 := t0+dT;
      If dir=+1 Then
        Begin { Direct Integration }
          dv1:=-woT*y0;
          v11:= v0+dv1;
          dy1:= woT*v0;
          y11:= y0+dy1;
          dv2:=-woT*y11;
          dy2:= woT*v11;
          v1 := v0+0.5*(dv1+dv2);
          y1 := y0+0.5*(dy1+dy2);
        End Else
          Begin { Transition matrixix }
            v1 := (1-0.5*woT2)*v0 - woT*y0;
            y1 := woT*v0 + (1-0.5*woT2)*y0;
          End;
      MapP(t1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      t0:=t1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
6: Begin
  WrTxtWXY(3,blac,1,1,'False Heun');
  t0:=0; v0:=0; y0:=1;
  MapP(t0,y0,p0,q0); Mark(p0,q0,120,100);
  For i:=1 to k Do
    Begin
      t1 := t0+dT;
      If dir=+1 Then
        Begin { Direct Integration }
          dv1:=-woT*y0;
          v11:= v0+dv1;
          dy1:= woT*v11;
          y11:= y0+dy1;
          dv2:=-woT*y11;
          v12:= v0+dv2;
          dy2:= woT*v12;
          v1 := v0+0.5*(dv1+dv2);
          y1 := y0+0.5*(dy1+dy2);
        End Else
        Begin { Transition matrix }
          v1 := (1-0.5*woT2)*v0 - woT*(1-0.5*woT2)*y0;
          y1 := woT*(1-0.5*woT2)*v0 + (1-woT2+0.5*woT4)*y0;
        End;
      MapP(t1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      t0:=t1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
7: Begin
  WrTxtWXY(3,blac,1,1,'Semi-False Heun');
  x0:=0; v0:=0; y0:=1;
  MapP(x0,y0,p0,q0);
  Mark(p0,q0,120,100);
  For i:=1 to k Do
    Begin
      x1 := x0+dT;
      If dir=+1 Then
        Begin { Direct Integration }
          dv1:=-woT*y0;
          v11:= v0+dv1;
          dy1:= woT*v0;
          y11:= y0+dy1;
          dv2:=-woT*y11;
          v12:= v0+dv2;
          dy2:= woT*v12;
          v1 := v0+0.5*(dv1+dv2);
          y1 := y0+0.5*(dy1+dy2);
        End Else
        Begin { Transition matrix }
          v1:=      (1-0.5*woT2)*v0 -      woT*y0;
          y1:=  woT*(1-0.5*woT2)*v0 + (1-0.5*woT2)*y0;
        End;
      MapP(x1,y1,p1,q1);
      MakeSline(p0,q0,p1,q1,120,100); Mark(p1,q1,120,100);
      x0:=x1; v0:=v1; y0:=y1; p0:=p1; q0:=q1;
    End;
  End;
End; { case}
End;
