// The one translation unit that compiles the header-only libraries' implementations.
// Their warnings are theirs: this file is built without the project's warning flags.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>

#define STB_IMAGE_IMPLEMENTATION
#define STBI_NO_STDIO_IF_UNUSED
#include <stb_image.h>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image_write.h>
