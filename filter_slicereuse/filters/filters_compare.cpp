// "Compare Mask Stacks": the method's similarity S of two mask stacks, layer by layer, and how
// far their grey levels differ; no mesh involved.
#include "filter_params.h"
#include "filters_common.h"
#include "slicereuse/printfiles/compare_mask_stacks.h"

namespace slicereuse::plugin {
namespace {

struct CompareParams {
  std::string stack_a;
  std::string stack_b;
  std::string report_file;
};

ParamList<CompareParams> compare_params() {
  ParamList<CompareParams> l;
  l.file(&CompareParams::stack_a, ParamType::FileOpen, "stack_a", "Stack A", "*.sl1 *.sl1s *.goo *.ctb",
         "choose the first mask stack (a folder of PNG images, an .sl1 archive, a .goo or a .ctb file)",
         "First mask stack: a folder of PNG images, a .sl1/.sl1s archive, an Elegoo .goo or a Chitubox .ctb file.")
      .file(&CompareParams::stack_b, ParamType::FileOpen, "stack_b", "Stack B", "*.sl1 *.sl1s *.goo *.ctb",
            "choose the second mask stack (a folder of PNG images, an .sl1 archive, a .goo or a .ctb file)",
            "Second mask stack: a folder of PNG images, a .sl1/.sl1s archive, an Elegoo .goo or a Chitubox .ctb file.")
      .file(&CompareParams::report_file, ParamType::FileSave, "report_file", "Report file (CSV)", "*.csv", nullptr,
            "Where to write one CSV row per layer (layer, similarity, differing pixels, largest grey "
            "difference, pixels differing by more than one level). Empty: no report is written.");
  return l;
}

Result run_compare_masks(const CompareParams& p, Host& host) {
  const auto start = std::chrono::steady_clock::now();

  const StackComparison c = compare_mask_stacks(p.stack_a, p.stack_b, p.report_file, host.progress());

  const double seconds = seconds_since(start);
  host.log(format("Compare Mask Stacks: %zu layers, min similarity %.9g at layer %zu, %llu differing pixels, "
                  "max grey difference %d at layer %zu, %llu pixels (share %.9g) differ by more than one level "
                  "(most at layer %zu), %.3f s",
                  c.layers.size(), c.min_similarity, c.worst_layer, (unsigned long long)c.differing_pixels,
                  c.max_grey_difference, c.max_grey_difference_layer, (unsigned long long)c.over_one_level_pixels,
                  c.over_one_level_share, c.over_one_level_layer, seconds));
  return {{"layers", int64_t(c.layers.size())},
          {"min_similarity", c.min_similarity},
          {"worst_layer", int64_t(c.worst_layer)},
          {"differing_pixels", int64_t(c.differing_pixels)},
          {"max_grey_difference", int64_t(c.max_grey_difference)},
          {"max_grey_difference_layer", int64_t(c.max_grey_difference_layer)},
          {"over_one_level_pixels", int64_t(c.over_one_level_pixels)},
          {"over_one_level_share", c.over_one_level_share},
          {"over_one_level_layer", int64_t(c.over_one_level_layer)},
          {"seconds", seconds}};
}

}  // namespace

FilterSpec compare_masks_filter() {
  const std::string description = std::string(
      "<p>Compares two stacks of mask images (folders of PNG images, .sl1 "
      "archives, .goo or .ctb files, in any pairing, e.g. from a transferred and a directly sliced member) layer by "
      "layer. A pixel is on when its grey level is at least 128 (binary masks are "
      "0 or 255). The similarity of a layer is S = 1 - (pixels on in one image and "
      "off in the other) / (all pixels), so for binary masks S = (pixels equal in "
      "both images) / (all pixels) and S = 1 means identical masks. The grey "
      "levels (of anti-aliased masks) are compared too: per layer the largest "
      "difference |a - b| between a pixel's levels a and b in the two images (0 "
      "to 255; 0 means identical images) and the number of pixels whose levels "
      "differ by more than one. "
      "Logs the lowest S and its layer, the total number of differing pixels, the "
      "largest grey difference and its layer, the pixels differing by more than one "
      "level (count and share of all pixels) and the layer with most of them (the "
      "first layer on ties); optionally writes one CSV row per layer. The stacks "
      "must have the same number of layers and image size. The current mesh is not "
      "used.</p>") +
      kReference;
  return typed_filter({FilterId::CompareMasks, "Compare Mask Stacks", "compare_mask_stacks", description,
                       Arity::None, kLayerClass | kMeasureClass, false},
                      compare_params(), run_compare_masks,
                      {"layers", "min_similarity", "worst_layer", "differing_pixels", "max_grey_difference",
                       "max_grey_difference_layer", "over_one_level_pixels", "over_one_level_share",
                       "over_one_level_layer", "seconds"});
}

}  // namespace slicereuse::plugin
