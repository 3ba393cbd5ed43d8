// libFuzzer target: decodeImage (stb_image behind a size limit) on arbitrary bytes. A decoded
// image must have the size it claims within the limit; it is then written as PNG with
// stb_image_write and decoded again, and must come back identical.
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <stb_image_write.h>

#include "core/image.h"

namespace {

constexpr const char* kName = "fuzz.png";
// Far below the default 8192: a tiny input may still claim a big image, and decoding one costs
// width x height x 4 bytes; the limit check itself is what matters here.
constexpr int kMaxDimension = 1024;
constexpr int kMaxRoundTripPixels = 64 * 64;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "fuzz_png: invariant broken: %s\n", what);
  std::abort();
}

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  reflect::Result<reflect::RgbaImage> image =
      reflect::decodeImage(data, size, kName, kMaxDimension);
  if (!image) {
    if (image.error().rfind(std::string(kName) + ": ", 0) != 0) {
      fail("error message does not start with the input's name");
    }
    return 0;
  }
  const reflect::RgbaImage& decoded = image.value();
  if (decoded.width < 1 || decoded.height < 1 || decoded.width > kMaxDimension ||
      decoded.height > kMaxDimension) {
    fail("decoded size outside the limit");
  }
  if (decoded.pixels.size() !=
      static_cast<size_t>(decoded.width) * static_cast<size_t>(decoded.height) * 4) {
    fail("pixel buffer does not match the size");
  }
  if (decoded.width * decoded.height > kMaxRoundTripPixels) return 0;

  std::vector<uint8_t> png;
  if (!stbi_write_png_to_func(appendBytes, &png, decoded.width, decoded.height, 4,
                              decoded.pixels.data(), decoded.width * 4)) {
    fail("cannot encode a decoded image");
  }
  reflect::Result<reflect::RgbaImage> again = reflect::decodeImage(png.data(), png.size(), kName);
  if (!again) fail("cannot decode our own PNG");
  if (again.value().width != decoded.width || again.value().height != decoded.height ||
      again.value().pixels != decoded.pixels) {
    fail("PNG round trip changed the image");
  }
  return 0;
}
