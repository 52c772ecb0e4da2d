#declare S = "a"
#if (strlen(S) = 1) #declare S =("a"
#if (strlen(S) = 1) #decla: unsupported ree Okd
