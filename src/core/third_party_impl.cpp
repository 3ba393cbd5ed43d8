// The one translation unit that compiles the header-only libraries' implementations the
// program uses. Their warnings are theirs: this file is built without the project's warning
// flags. (tinyobjloader, the OBJ parser's test oracle, is compiled into the tests alone:
// tests/unit/tinyobjloader_impl.cpp and docs/obj.md.)
#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO_IF_UNUSED
#include <stb_image.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
