// A planted layer violation: core must not include GL (tests/CMakeLists.txt expects the
// layer check to fail on this file).
#include "gfx/gl.h"
