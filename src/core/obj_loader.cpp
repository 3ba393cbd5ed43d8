#include "core/obj_loader.h"

#include <algorithm>
#include <fstream>
#include <string_view>

#include "core/obj_stream.h"

namespace reflect {

Result<LoadedMesh> parseObj(const std::string& text, const std::string& name,
                            const ObjLimits& limits) {
  if (text.size() > limits.maxBytes) {
    return Result<LoadedMesh>::failure(name + ": file is " + std::to_string(text.size()) +
                                       " bytes, over the limit of " +
                                       std::to_string(limits.maxBytes));
  }
  ObjStreamParser parser(name, limits);
  parser.feed(text);
  return parser.finish();
}

Result<LoadedMesh> loadObjFile(const std::string& path, const ObjLimits& limits) {
  using Out = Result<LoadedMesh>;
  std::ifstream file(path, std::ios::binary | std::ios::ate);
  if (!file) return Out::failure(path + ": cannot open file");
  const std::streamoff size = file.tellg();
  if (size < 0) return Out::failure(path + ": cannot read file");
  if (static_cast<size_t>(size) > limits.maxBytes) {
    return Out::failure(path + ": file is " + std::to_string(size) + " bytes, over the limit of " +
                        std::to_string(limits.maxBytes));
  }
  file.seekg(0);
  // The file in pieces, parsed as they are read: the text is never held whole.
  ObjStreamParser parser(path, limits);
  std::string piece(kObjReadPiece, '\0');
  std::streamoff left = size;
  while (left > 0) {
    const std::streamsize count =
        static_cast<std::streamsize>(std::min<std::streamoff>(left, kObjReadPiece));
    if (!file.read(piece.data(), count)) return Out::failure(path + ": cannot read file");
    left -= count;
    if (!parser.feed(std::string_view(piece.data(), static_cast<size_t>(count)))) break;
  }
  return parser.finish();
}

}  // namespace reflect
