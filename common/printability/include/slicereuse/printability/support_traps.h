#pragma once
// support_traps: the resin traps of a supported print, found over its whole stack before a layer
// is written, each then lit in every layer it spans.
//
// Pillars, heads and the part stand a few pixels apart and close pockets of air, layer after
// layer; a print keeps their resin. Lit layer by layer, a pocket lit in some layers and not in
// others would trap the resin between them. So the air is followed in 3D as the printability
// check follows it (check_layers.h: pixels <= 100, joined in a layer by 4-connectivity and to the
// layer below through 10 shared pixels, regions under 4 pixels taken as solid), and a resin trap
// (air reaching neither the image border, nor the top layer's air, nor layer 0) is lit whole when
// it holds at most max_pixels pixels over its layers and either touches the supports (a pixel of
// it at or next to, 8 neighbours, a lit pixel of the supports' own binary mask, in any of its
// layers) or never holds, in one layer, the 10 pixels through which air drains (such a hole is a
// trap whatever the print); so is every closed speck of air under the 4 pixels the check counts
// (it takes them as solid). A hole of the part no support touches stays, as does air that drains.
//
// Use: a SupportTraps; each layer's mask (every part; mask_png.h) and the supports' binary mask
// of it through prepare_trap_layer (thread-safe: on the threads that draw the layers) and then,
// in order from layer 0, add_layer; finish() once; then light(k, mask), on the mask layer k was
// prepared from, sets its traps' pixels to 255 (fully lit, which every print file's levels
// hold), a row's runs still increasing and disjoint, runs of one level side by side joined.
// lit(k): whether light changes layer k. traps(): the traps lit; lit_pixels(): the pixels lit,
// specks included, over all layers.
// Memory: the runs of the pockets of air (regions not reaching the border) of every layer, and
// the air of one layer. Throws Error when a layer's masks differ in size from each other or from
// layer 0's.
// kSupportTrapMm3: the largest trap lit. On the supports' sweep of 100 parts the largest the
// supports close held 14.6 mm³ (a chimney between packed pillars, 10 mm tall, 6.6 mm³); a cavity
// of a part, such as a hearing-aid shell's inside, holds hundreds: a larger trap is left, and the
// check reports it.
#include <cstddef>
#include <cstdint>
#include <memory>

#include "slicereuse/png/mask_png.h"

namespace slicereuse {

constexpr double kSupportTrapMm3 = 20;

struct TrapLayerAir;

struct TrapLayer {
  TrapLayer();
  ~TrapLayer();
  TrapLayer(TrapLayer&&) noexcept;
  TrapLayer& operator=(TrapLayer&&) noexcept;
  std::unique_ptr<TrapLayerAir> air;
};

TrapLayer prepare_trap_layer(const MaskRuns& mask, const MaskRuns& support_runs);

class SupportTraps {
 public:
  explicit SupportTraps(uint64_t max_pixels);
  ~SupportTraps();
  SupportTraps(const SupportTraps&) = delete;
  SupportTraps& operator=(const SupportTraps&) = delete;

  void add_layer(TrapLayer layer);
  void finish();
  size_t traps() const;  // lit, after finish
  uint64_t lit_pixels() const;
  bool lit(size_t k) const;
  void light(size_t k, MaskRuns& mask) const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace slicereuse
