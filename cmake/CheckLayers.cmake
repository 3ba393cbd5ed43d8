# Fails when a source file includes a layer it may not see. Run at build time (target
# reflect_layers) and as a ctest test, with
#   cmake -DSOURCE_DIR=src -DLAYERS="core:core;gfx:core,gfx;..." -P CheckLayers.cmake
# Each LAYERS entry is "folder:allowed folders". A quoted include "X/..." must name an allowed
# folder X; the system headers of GL, EGL, Emscripten and Embree belong to one layer each.
if(NOT SOURCE_DIR OR NOT LAYERS)
  message(FATAL_ERROR "usage: cmake -DSOURCE_DIR=... -DLAYERS=... -P CheckLayers.cmake")
endif()
string(REPLACE "|" ";" LAYERS "${LAYERS}")

# system header prefix -> the only layers that may include it
set(system_owners "GLES:gfx" "EGL:platform" "emscripten:platform" "embree:reference")

set(violations "")
foreach(entry IN LISTS LAYERS)
  string(REPLACE ":" ";" parts "${entry}")
  list(GET parts 0 layer)
  list(GET parts 1 allowed)
  string(REPLACE "," ";" allowed "${allowed}")
  file(GLOB_RECURSE files "${SOURCE_DIR}/${layer}/*.h" "${SOURCE_DIR}/${layer}/*.cpp")
  foreach(file IN LISTS files)
    file(STRINGS "${file}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*[<\"]")
    foreach(line IN LISTS includes)
      if(line MATCHES "#[ \t]*include[ \t]*\"([^/\"]+)/")
        list(FIND allowed "${CMAKE_MATCH_1}" found)
        if(found EQUAL -1)
          list(APPEND violations "${file}: ${layer} may not include \"${CMAKE_MATCH_1}/...\"")
        endif()
      elseif(line MATCHES "#[ \t]*include[ \t]*<([A-Za-z0-9_]+)")
        set(header "${CMAKE_MATCH_1}")
        foreach(owner IN LISTS system_owners)
          string(REPLACE ":" ";" pair "${owner}")
          list(GET pair 0 prefix)
          list(GET pair 1 owning)
          string(FIND "${header}" "${prefix}" at)
          if(at EQUAL 0 AND NOT layer STREQUAL owning)
            list(APPEND violations "${file}: ${layer} may not include <${header}...> (only ${owning})")
          endif()
        endforeach()
      endif()
    endforeach()
  endforeach()
endforeach()

if(violations)
  list(JOIN violations "\n  " text)
  message(FATAL_ERROR "layer violations:\n  ${text}")
endif()
message(STATUS "layers: every include is allowed")
