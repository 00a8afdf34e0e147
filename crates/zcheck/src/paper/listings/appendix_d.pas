Procedure Func;
{ Three Bodies }
Var   x1o,y1o,x2o,y2o,x3o,y3o : Double;
      v1o,w1o,v2o,w2o,v3o,w3o : Double;
      x1 ,y1 ,x2 ,y2 ,x3 ,y3  : Double;
      v1 ,w1 ,v2 ,w2 ,v3, w3  : Double;
      p1o,q1o,p2o,q2o,p3o,q3o : Integer;
      p1 ,q1 ,p2 ,q2 ,p3 ,q3  : Integer;
      r12,r13,r23,c3,dT,Cf    : Double;
      dEn,Eno,eps            : Double;
      si,co                  : Single;
      k                      : LongInt;

Begin
SicCoc(30*wrad,si,co);
dT:=0.01;
Cf:=0.3; { experimental control factor }
{ Standard Euler with Energy control }
  eps:=0.01;
  x1o:=-co; y1o:=-si; v1o:=-co; w1o:=-si;
  x2o:= co; y2o:=-si; v2o:= co; w2o:=-si;
  x3o:=  0; y3o:=  1; v3o:= eps; w3o:=  1;
  MapP(x1o,y1o,p1o,q1o); Mark(p1o,q1o,  0,100);
  MapP(x2o,y2o,p2o,q2o); Mark(p2o,q2o, 60,100);
  MapP(x3o,y3o,p3o,q3o); Mark(p3o,q3o,120,100);
  { Initial total energy }
  r12:=Sqr(x2o-x1o)+Sqr(y2o-y1o);
  r13:=Sqr(x3o-x1o)+Sqr(y3o-y1o);
  r23:=Sqr(x3o-x2o)+Sqr(y3o-y2o);
  Eno:=(sqr(v1o)+sqr(w1o)+sqr(v2o)+sqr(w2o)+sqr(v3o)+sqr(w3o))/2
        -Sqrt(1/r12)-Sqrt(1/r23)-Sqrt(1/r13);
  ASM FNINIT END;
  For k:=1 to 100000 Do
  Begin
  r12:=Sqr(x2o-x1o)+Sqr(y2o-y1o);
  r13:=Sqr(x3o-x1o)+Sqr(y3o-y1o);
  r23:=Sqr(x3o-x2o)+Sqr(y3o-y2o);
  { Actual energy difference }
  dEn:=(sqr(v1o)+sqr(w1o)+sqr(v2o)+sqr(w2o)+sqr(v3o)+sqr(w3o))/2
        -Sqrt(1/r12)-Sqrt(1/r23)-Sqrt(1/r13)-Eno;
  ASM FNINIT END;
  { Control by partial derivatives dE/dv1 etc. }
  v1:=v1o+dT*( (x2-x1)/r12+(x3-x1)/r13 - Cf*dEn*v1o );
  v2:=v2o+dT*( (x3-x2)/r23+(x1-x2)/r12 - Cf*dEn*v2o );
  v3:=v3o+dT*( (x1-x3)/r13+(x2-x3)/r23 - Cf*dEn*v3o );
  w1:=w1o+dT*( (y2-y1)/r12+(y3-y1)/r13 - Cf*dEn*w1o );
  w2:=w2o+dT*( (y3-y2)/r23+(y1-y2)/r12 - Cf*dEn*w2o );
  w3:=w3o+dT*( (y1-y3)/r13+(y2-y3)/r23 - Cf*dEn*w3o );
x1:=x1o+dT*v1o;
y1:=y1o+dT*w1o;
x2:=x2o+dT*v2o;
y2:=y2o+dT*w2o;
x3:=x3o+dT*v3o;
y3:=y3o+dT*w3o;
MapP(x1,y1,p1,q1);
MapP(x2,y2,p2,q2);
MapP(x3,y3,p3,q3);
MakeSline(p1o,q1o,p1,q1, 0,100);
MakeSline(p2o,q2o,p2,q2, 60,100);
MakeSline(p3o,q3o,p3,q3,120,100);
x1o:=x1; y1o:=y1;
x2o:=x2; y2o:=y2;
x3o:=x3; y3o:=y3;
v1o:=v1; w1o:=w1;
v2o:=v2; w2o:=w2;
v3o:=v3; w3o:=w3;
p1o:=p1; q1o:=q1;
p2o:=p2; q2o:=q2;
p3o:=p3; q3o:=q3;
End;
End;
