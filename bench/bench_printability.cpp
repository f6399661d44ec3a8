// Cost of the printability checks (check_layers.h) per layer on a real print file, apart from
// reading and decoding its layers into runs (MaskStack, mask_runs_of): the checks a job runs on
// the rasterizer's runs.
// Usage: bench_printability FILE PIXEL_X_MM PIXEL_Y_MM LAYER_MM [REPEAT]
// Every layer is read and decoded into runs first; then the whole stack is checked REPEAT times
// (default 1; more to profile the checks alone). Prints the layers, the lit share of the pixels,
// the time to read and decode them, the checker's time per layer in the median repeat (mean,
// median, largest, and its layer), how much of it is in order (add_layer) and how much the
// layers' preparation (prepare_layer, in parallel in a job), the findings per kind and each
// finding's layers and box.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <vector>

#include "mask_stack.h"
#include "slicereuse/printability/check_layers.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  if (argc != 5 && argc != 6) {
    std::fprintf(stderr, "usage: bench_printability FILE PIXEL_X_MM PIXEL_Y_MM LAYER_MM [REPEAT]\n");
    return 2;
  }
  using Clock = std::chrono::steady_clock;
  const auto ms_since = [](Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
  };
  MaskStack stack(argv[1]);
  const int repeat = argc == 6 ? std::max(1, std::atoi(argv[5])) : 1;
  std::vector<uint8_t> bytes;
  std::vector<MaskRuns> layers;
  double decode_ms = 0;
  uint64_t lit = 0, pixels = 0, mask_runs = 0;
  int width = 0, height = 0;
  for (size_t k = 0; k < stack.layers(); ++k) {
    MaskImage image;
    auto t = Clock::now();
    stack.read(k, bytes);
    stack.decode(k, bytes, image);
    decode_ms += ms_since(t);
    width = image.width;
    height = image.height;
    pixels += image.pixels.size();
    for (const uint8_t p : image.pixels) lit += p != 0;
    t = Clock::now();
    layers.push_back(mask_runs_of(image));  // what the rasterizer gives a job's checks
    decode_ms += ms_since(t);
    mask_runs += layers.back().levels.size();
  }
  // Each repeat checks copies of the layers, as a job hands its layers over; the copy is untimed.
  // A layer's time is its preparation's (prepare_layer: in parallel in a job) and the checker's in
  // order (add_layer), timed apart.
  std::vector<std::vector<double>> repeats;
  std::vector<double> in_order_ms;  // per repeat
  PrintabilityReport r;
  double finish_ms = 0;
  for (int i = 0; i < repeat; ++i) {
    LayerChecker checker(std::atof(argv[2]), std::atof(argv[3]), std::atof(argv[4]));
    std::vector<double> ms;
    double in_order = 0;
    for (const MaskRuns& layer : layers) {
      MaskRuns copy = layer;
      auto t = Clock::now();
      PreparedLayer prepared = prepare_layer(std::move(copy));
      const double prepare_ms = ms_since(t);
      t = Clock::now();
      checker.add_layer(std::move(prepared));
      in_order += ms_since(t);
      ms.push_back(prepare_ms + ms_since(t));
    }
    in_order_ms.push_back(in_order);
    const auto t = Clock::now();
    r = checker.finish();
    finish_ms = ms_since(t);
    repeats.push_back(std::move(ms));
  }
  const auto total_of = [](const std::vector<double>& v) {
    double sum = 0;
    for (const double x : v) sum += x;
    return sum;
  };
  std::vector<size_t> order(repeats.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return total_of(repeats[a]) < total_of(repeats[b]); });
  const size_t median = order[order.size() / 2];
  const std::vector<double>& check_ms = repeats[median];
  std::vector<double> sorted = check_ms;
  std::sort(sorted.begin(), sorted.end());
  const double total = total_of(check_ms);
  const size_t worst = size_t(std::max_element(check_ms.begin(), check_ms.end()) - check_ms.begin());
  std::printf("%zu layers of %d x %d, %.2f%% of pixels lit\n", r.layers, width, height, 100.0 * double(lit) / double(pixels));
  std::printf("read + decode into runs: %.1f ms (%.2f ms per layer), %.0f runs of one level per layer\n", decode_ms,
              decode_ms / double(r.layers), double(mask_runs) / double(r.layers));
  std::printf("check (median of %d): %.1f ms, per layer mean %.2f ms, median %.2f ms, largest %.2f ms (layer %zu); finish %.2f ms\n",
              repeat, total, total / double(r.layers), sorted[sorted.size() / 2], sorted.back(), worst, finish_ms);
  std::printf("of which in order (add_layer): %.1f ms, %.2f ms per layer; prepared (prepare_layer): %.1f ms\n",
              in_order_ms[median], in_order_ms[median] / double(r.layers), total - in_order_ms[median]);
  for (size_t kind = 0; kind < kFindingKinds; ++kind)
    std::printf("%s: %zu\n", finding_kind_name(FindingKind(kind)), r.counts[kind]);
  std::printf("trapped: %.4g mm3\n", r.trapped_mm3());
  for (const Finding& f : r.findings)
    std::printf("  %s layers %zu-%zu, pixels [%d, %d) x [%d, %d)\n", finding_kind_name(f.kind), f.first_layer,
                f.last_layer, f.x0, f.x1, f.y0, f.y1);
  return 0;
}
