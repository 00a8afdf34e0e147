Procedure Integ;
{ Rotational differential equations for an aircraft
  Integration by False Euler
  Simplified attitude controller
  Command input in degrees for rollangle and pitchangle }
Var   sPhi,cPhi,sThe,cThe,sPsi,cPsi,icThe: Double;
Const Jx=0.6; Jy=1; Jz=1.5;
      dampP=2;   contPhi=0.06;
      dampQ=3;   contThe=0.10;
      dampR=1;   contPsi=1;
      eps =1E-5;
      wrad=pi/180;
      dT  =0.1;
      dT1 =dT/wrad;
Begin
{ Fast Sines and Cosines }
siccoc(wrad*Phi,sPhi,cPhi);
siccoc(wrad*The,sThe,cThe);
siccoc(wrad*Psi,sPsi,cPsi);
{ Rolldamper, Pitchdamper, Yawdamper
  Rollcontroller, Pitchcontroller, Yawrate by Rollangle
  Phic = Command Rollangle
  Thec = Command Pitchangle
  Txc,Tyc,Tzc = Command Torques }
Tx:=-dampP*wx+Txc;
Ty:=-dampQ*wy+Tyc;
Tz:=-dampR*wz-contPsi*sPhi*cThe +Tzc;
If CO=1 Then
Begin
While Phi> 180 Do Phi:=Phi-360;
While Phi<-180 Do Phi:=Phi+360;
While The> 180 Do The:=The-360;
While The<-180 Do The:=The+360;
Tx:=Tx-contPhi*(Phi-Phic);
Ty:=Ty-contThe*(The-Thec);
End;
{ Body fixed coordinate system in principal axes direction
{ Integration of angular velocities }
wx:=wxo + dT*(wyo*wzo*(Jy-Jz)+Tx)/Jx;
wy:=wyo + dT*(wzo*wxo*(Jz-Jx)+Ty)/Jy;
wz:=wzo + dT*(wxo*wyo*(Jx-Jy)+Tz)/Jz;
wxo:=wx; wyo:=wy; wzo:=wz;
{ Trap gimbal lock singularity }
If Abs(cThe)<eps Then
Begin
If cThe>0 Then cThe:=eps Else cThe:=-eps;
End;
icThe:=1/cThe;
{ Integration of Euler angle derivatives }
Phi:=Phi + dT1*(wx+wy*sPhi*sThe*icThe+wz*cPhi*sThe*icThe);
The:=The + dT1*( wy*cPhi -wz*sPhi );
Psi:=Psi + dT1*( wy*sPhi*icThe +wz*cPhi*icThe );
WrNumWin(1,grel,1,'Phi', Phi);
WrNumWin(1,grel,2,'The',-The);
WrNumWin(1,grel,3,'Psi',-Psi);
{ Rotation matrix }
o11:=+cpsi*cthe;
o12:=-spsi*cphi+cpsi*sThe*sphi;
o13:=+spsi*sphi+cpsi*sThe*cphi;
o21:=+spsi*cthe;
o22:=+cpsi*cphi+spsi*sThe*sphi;
o23:=-cpsi*sphi+spsi*sThe*cphi;
o31:=-sThe;
o32:=+cThe*sphi;
o33:=+cThe*cphi;
End;
