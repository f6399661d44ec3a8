#pragma once
// The pictures a print file carries, made from a top view (top_view.h).
//
// thumbnail_png: a top view as the picture PrusaSlicer puts into an .sl1 archive
// (thumbnail/thumbnailWxH.png): an 8-bit RGBA PNG of width x height pixels (out replaced) with
// the part framed to fill it (its covered cells' bounding box centred, proportions kept, a 5 %
// margin on the tighter side), transparent around it, in resin orange (PrusaSlicer's colour of
// Prusa Orange Tough, #FF8040) shaded by height: the top layers at full brightness, the first
// at 40 %. Each pixel is the mean of 4 x 4 samples of the map, so the outline is anti-aliased
// (alpha = the share of samples on the part) at any scale. Seen from above, not mirrored: +x to
// the right, +y up. A map with no covered cell gives a fully transparent picture.
#include <cstdint>
#include <vector>

#include "slicereuse/raster/top_view.h"

namespace slicereuse {

void thumbnail_png(const HeightMap& view, int width, int height, std::vector<uint8_t>& out);

// rgb565_preview: a top view as a printer's preview (.goo, .ctb, Anycubic headers): width x height
// RGB565 pixels, row-major from the top, showing where the part stands on the build plate: the
// whole display area fitted into the picture at its true proportions and centred, +x to the
// right and +y up (the display's mirrors undone), each pixel a grey level round(255 * share) of
// its 4 x 4 samples that fall on covered cells. Why the plate rather than the part: a printer's
// screen shows where on the plate the job will stand.
std::vector<uint16_t> rgb565_preview(const HeightMap& view, int width, int height);

}  // namespace slicereuse
