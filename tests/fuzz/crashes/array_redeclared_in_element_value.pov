#declare A = array[2]
#declare A[0] = #declare A = array[2] 5;
