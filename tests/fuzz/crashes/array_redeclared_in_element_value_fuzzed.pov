
        #declare TG = array[2]
        #declare TG[0] = #declare Ball = sphere { 0, 1 pigment { rgb 1 } translate y }
     #declare TG = array[2]
        #declare TG[0] = 5;
 (3) + 1;
        #ifdef (R) #decl6);
        #macrobal(V) #declare G = V   