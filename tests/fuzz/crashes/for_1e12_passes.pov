#for (I, 0, 1e12)
#end
