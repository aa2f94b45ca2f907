// Includes a file that does not exist, on line 2.
#include "missing.cginc"
