#include "slice_files_binary_layout.h"

namespace slicereuse::detail {

const char* section_name(uint32_t id) {
  switch (id) {
    case kLayerZ: return "layer_z";
    case kLayerBegin: return "layer_begin";
    case kContourBegin: return "contour_begin";
    case kContourOpen: return "contour_open";
    case kXyz: return "xyz";
    case kFace: return "face";
    case kEdge: return "edge";
    case kT: return "t";
    case kSourceFaces: return "source_faces";
    case kMapFace: return "face";
    case kMapBary: return "bary";
    default: return "unknown";
  }
}

const char* container_kind_noun(uint32_t kind) {
  if (kind == uint32_t(FileKind::Contours) || kind == uint32_t(FileKind::Encoding)) return kind_noun(FileKind(kind));
  return kind == kMapFileKind ? "a map file" : nullptr;
}

std::vector<uint32_t> section_ids(FileKind kind) {
  if (kind == FileKind::Contours) return {kLayerZ, kLayerBegin, kContourBegin, kContourOpen, kXyz};
  return {kLayerZ, kLayerBegin, kContourBegin, kContourOpen, kFace, kEdge, kT};
}

uint64_t section_bytes(uint32_t id, uint64_t layers, uint64_t contours, uint64_t points) {
  switch (id) {
    case kLayerZ: return 8 * layers;
    case kLayerBegin: return 8 * (layers + 1);
    case kContourBegin: return 8 * (contours + 1);
    case kContourOpen: return contours;
    case kXyz: return 24 * points;
    case kFace: return 4 * points;
    case kEdge: return points;
    case kT: return 8 * points;
    default: return 0;
  }
}

unsigned char* section_data(Slices& s, uint32_t id) {
  switch (id) {
    case kLayerZ: return reinterpret_cast<unsigned char*>(s.layer_z.data());
    case kLayerBegin: return reinterpret_cast<unsigned char*>(s.layer_begin.data());
    case kContourBegin: return reinterpret_cast<unsigned char*>(s.contour_begin.data());
    case kContourOpen: return s.contour_open.data();
    case kXyz: return reinterpret_cast<unsigned char*>(s.xyz.data());
    case kFace: return reinterpret_cast<unsigned char*>(s.face.data());
    case kEdge: return s.edge.data();
    case kT: return reinterpret_cast<unsigned char*>(s.t.data());
    default: return nullptr;
  }
}

}  // namespace slicereuse::detail
