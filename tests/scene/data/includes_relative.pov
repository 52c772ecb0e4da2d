// Parsed by directives_test.cpp: the include is found next to this file.
#declare Outer = 0;
#include "lib/scoping.inc"
