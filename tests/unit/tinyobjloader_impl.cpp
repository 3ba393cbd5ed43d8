// tinyobjloader's implementation, for the tests alone: obj_stream_test.cpp holds the streaming
// parser's meshes to the ones tinyobjloader makes of the same text (docs/obj.md: why the program
// itself does not use it). Built without the project's warning flags: its warnings are its own.
#define TINYOBJLOADER_IMPLEMENTATION
#include <tiny_obj_loader.h>
