#declare I=0; #while (I < 10) #declare I = I + #end
