#switch(1)#case(#case(1)#end 1)
