#include "slicereuse/raster/top_view.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "slicereuse/png/mask_png.h"
#include "slicereuse/raster/rasterize_layer.h"

namespace slicereuse {

TopView::TopView(const PrinterProfile& display, size_t layers) : layers_(layers) {
  const double width_mm = 1e-3 * display.width_px * display.pixel_size_x_um;
  const double height_mm = 1e-3 * display.height_px * display.pixel_size_y_um;
  const double cell_mm = std::max(1e-3 * std::min(display.pixel_size_x_um, display.pixel_size_y_um),
                                  std::max(width_mm, height_mm) / kTopViewCells);
  // Whole cells covering the display, centred on it as the display is on the model's origin.
  grid_.width_px = std::min(kTopViewCells, int(std::ceil(width_mm / cell_mm)));
  grid_.height_px = std::min(kTopViewCells, int(std::ceil(height_mm / cell_mm)));
  grid_.pixel_size_x_um = grid_.pixel_size_y_um = 1e3 * cell_mm;
  grid_.offset_x_mm = display.offset_x_mm;
  grid_.offset_y_mm = display.offset_y_mm;
  map_.cols = grid_.width_px;
  map_.rows = grid_.height_px;
  map_.level.assign(size_t(map_.cols) * size_t(map_.rows), 0);
}

std::unique_ptr<TopView::Canvas> TopView::take() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (idle_.empty()) return std::make_unique<Canvas>(size_t(grid_.width_px) * size_t(grid_.height_px), 0);
  std::unique_ptr<Canvas> canvas = std::move(idle_.back());
  idle_.pop_back();
  return canvas;
}

void TopView::give(std::unique_ptr<Canvas> canvas) {
  std::lock_guard<std::mutex> lock(mutex_);
  idle_.push_back(std::move(canvas));
}

bool TopView::draws(size_t k) const {
  // The top layer of its band: the band of layer k + 1 differs, or k is the last layer.
  const size_t bands = std::min(layers_, kTopViewLayers);
  return k * bands / layers_ != (k + 1) * bands / layers_;
}

void TopView::add(const LayerView& layer, size_t k) {
  if (!draws(k)) return;
  thread_local MaskRuns runs;
  rasterize_layer_runs(layer, grid_, runs);
  const uint8_t level = layers_ > 1 ? uint8_t(1 + k * 254 / (layers_ - 1)) : uint8_t(255);
  std::unique_ptr<Canvas> canvas = take();
  uint8_t* const cells = canvas->data();
  for (int r = 0; r < runs.height; ++r) {
    uint8_t* const row = cells + size_t(r) * size_t(runs.width);
    for (uint32_t i = runs.row_begin[size_t(r)]; i < runs.row_begin[size_t(r) + 1]; ++i)
      for (int c = runs.columns[2 * i]; c < runs.columns[2 * i + 1]; ++c) row[c] = std::max(row[c], level);
  }
  give(std::move(canvas));
}

const HeightMap& TopView::finish() {
  std::lock_guard<std::mutex> lock(mutex_);
  for (const std::unique_ptr<Canvas>& canvas : idle_)
    for (size_t i = 0; i < map_.level.size(); ++i) map_.level[i] = std::max(map_.level[i], (*canvas)[i]);
  idle_.clear();
  return map_;
}

}  // namespace slicereuse
