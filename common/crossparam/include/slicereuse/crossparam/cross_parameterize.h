#pragma once
// cross_parameterize: a map between two meshes of one product family that differ in
// connectivity (other vertex count, faces, order), with the method's in-plane constraint: a
// source vertex at height h maps onto the target at height h.
//
// Input: source and target meshes and options (landmark pairs, in_plane).
// Output: the SurfaceMap (one target point per source vertex), a quality report, a patch id
// per vertex of both meshes (the same id marks corresponding regions, for colouring), and the
// registered source vertices.
// Throws Error with a message that names the problem for input it cannot map (see the .cpp
// header comment for the approach and its limits): meshes of different genus, connected
// components or boundary loops (both values named), bad landmarks, or, without landmarks, a
// pair the registration cannot bring together (the message asks for landmarks).
// Genus 1 and higher is handled (a handle, a torus): nothing in the approach needs a disc or a
// sphere, only the same topology on both sides. Open meshes are handled alike.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "slicereuse/crossparam/surface_map.h"
#include "slicereuse/mesh/mesh.h"
#include "slicereuse/util/progress.h"

namespace slicereuse {

struct CrossParamOptions {
  bool in_plane = true;
  // Corresponding points, source_landmarks[i] <-> target_landmarks[i] (equal lengths; may be
  // empty: then the correspondence is found automatically or refused with a clear message).
  std::vector<std::array<double, 3>> source_landmarks;
  std::vector<std::array<double, 3>> target_landmarks;
};

struct CrossParamQuality {
  // Source triangles whose image is folded over (its normal against that of the registered
  // source triangle, or no area); 0 expected, and the map is untangled until it is.
  uint64_t flipped_triangles = 0;
  double max_height_error = 0;     // max |z(image) - z(source vertex)| (mm)
  double rms_height_error = 0;
  double area_distortion = 0;      // mean |log(image area / source area)| over triangles
  double angle_distortion = 0;     // mean |image angle - source angle| over corners (degrees)
  uint64_t patches = 0;
  int genus = 0;                   // of the source (equal to the target's, or refused)
  double seconds = 0;
};

struct CrossParamResult {
  SurfaceMap map;
  CrossParamQuality quality;
  std::vector<uint32_t> source_patch;  // per source vertex
  std::vector<uint32_t> target_patch;  // per target vertex; same id = corresponding patch
  // Per source vertex (3 each), its position after alignment and registration: the point its
  // image was sought from (on the target's level set at the vertex's own height in plane; with
  // in_plane = false the nearest target surface point facing the same way), before untangling
  // moved the images of folded triangles, if any.
  // What the registration did, apart from the projection: for inspection and tests.
  std::vector<double> registered;
};

CrossParamResult cross_parameterize(const Mesh& source, const Mesh& target, const CrossParamOptions& options,
                                    const Progress& progress = {});

}  // namespace slicereuse
