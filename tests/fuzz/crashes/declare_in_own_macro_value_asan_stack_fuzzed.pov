
         #macro Inc(V) #declare V =       Inc(K)
       #end
        #declare K = 10;
        Inc(K)
        #dsFphem L = 10;
        Inc(L + 0)mesh
           #macro Inc(V) #declare V = V spiral2+ 1warning; #ef 0)
    