// mask_picture: the README's picture of one anti-aliased layer next to its binary mask.
//   mask_picture --printer ID --faces N --out FILE.png
// Slices the family's arch base (family/family.h) at half its height, rasterizes that layer for
// the preset ID (printer_presets.h), binary and anti-aliased (gamma 1), cuts the same window of
// kWindow x kWindow pixels around the part's top-most lit pixel (where the outline curves) out
// of both, and writes them side
// by side, each pixel drawn as a kZoom x kZoom square, binary on the left, as an 8-bit grey PNG.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "family.h"
#include "slicereuse/png/mask_png.h"
#include "slicereuse/printer/printer_presets.h"
#include "slicereuse/raster/rasterize_layer.h"
#include "slicereuse/slicing/slice_layers.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"

using namespace slicereuse;

namespace {

constexpr int kWindow = 64, kZoom = 6, kGap = 2;

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string printer = "prusa_sl1s_speed", out;
    test::FamilyOptions family;
    family.faces = 200000;
    for (int i = 1; i + 1 < argc; i += 2) {
      const std::string k = argv[i], v = argv[i + 1];
      if (k == "--printer") printer = v;
      else if (k == "--faces") family.faces = std::strtoull(v.c_str(), nullptr, 10);
      else if (k == "--out") out = v;
      else throw Error("unknown option " + k + " (options: --printer ID, --faces N, --out FILE.png)");
    }
    if (out.empty()) throw Error("--out FILE.png is required");
    const Mesh mesh = make_family_base(family);
    SliceOptions options;
    options.thickness = family.height / 2;
    options.encoding = false;
    const Slices s = slice_layers(mesh, options);  // layer 0 lies at a quarter, layer 1 at 3/4
    PrinterProfile binary = printer_preset(printer).profile, grey = binary;
    binary.antialiasing = false;
    grey.antialiasing = true;
    grey.gamma = 1;
    const MaskImageLayout image = mask_image_layout(binary);
    const size_t pixels = size_t(image.width) * size_t(image.height);
    std::vector<uint8_t> a(pixels), b(pixels);
    rasterize_layer(s, 1, binary, a.data());
    rasterize_layer(s, 1, grey, b.data());
    // The window: centred on the first lit pixel in row order.
    const size_t first = size_t(std::find(a.begin(), a.end(), 255) - a.begin());
    if (first == pixels) throw Error("the layer is empty on this display");
    const int cx = int(first % size_t(image.width)), cy = int(first / size_t(image.width));
    const int x0 = std::clamp(cx - kWindow / 2, 0, image.width - kWindow),
              y0 = std::clamp(cy - kWindow / 2, 0, image.height - kWindow);
    const int side = kWindow * kZoom, W = 2 * side + kGap * kZoom;
    std::vector<uint8_t> picture(size_t(W) * size_t(side), 128);
    for (int y = 0; y < side; ++y)
      for (int x = 0; x < side; ++x) {
        const size_t from = size_t(y0 + y / kZoom) * size_t(image.width) + size_t(x0 + x / kZoom);
        picture[size_t(y) * size_t(W) + size_t(x)] = a[from];
        picture[size_t(y) * size_t(W) + size_t(side + kGap * kZoom + x)] = b[from];
      }
    std::vector<uint8_t> png;
    encode_mask_png(picture.data(), W, side, 8, png);
    AtomicFile file(out);
    file.write(png.data(), png.size());
    file.commit();
    std::printf("%s: layer at z = %g mm, %s, window %dx%d px at (%d, %d)\n", out.c_str(), s.layer_z[1],
                printer.c_str(), kWindow, kWindow, x0, y0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "mask_picture: %s\n", e.what());
    return 1;
  }
}
