// The parameters Make Print Job and Make Plate Job share: how their members' layers are made.
#include "filters_common.h"

namespace slicereuse::plugin {

ParamList<JobLayers> job_layer_params(const char* encoding_tooltip) {
  ParamList<JobLayers> l;
  l.file(&JobLayers::encoding_file, ParamType::FileOpen, "encoding_file", "Source encoding file", "*.enc *.srb",
         nullptr, encoding_tooltip)
      .number(&JobLayers::layer_thickness, "layer_thickness", "Layer thickness (mm)", 0.1, Range::above(0, "mm"),
              "Used when slicing directly (no encoding file): distance between slicing planes, in mm. With an "
              "encoding file, the encoding's layers are used.")
      .number(&JobLayers::z_start, "z_start", "Start height (mm)", kLowestVertexZStart, Range::any(),
              "Used when slicing directly: bottom of the first layer, in mm; at or below -1e29 (the default): the "
              "lowest vertex of the mesh (of all members, on a plate).")
      .flag(&JobLayers::strict, "strict", "Strict reuse", false,
            "With an encoding file: off (the default), a member whose faces are not those of the encoding's mesh "
            "(another connectivity) is sliced directly on the encoding's layers, and the result says why; on, "
            "such a member fails the job.");
  return l;
}

PlateJobOptions plate_job_options(const JobLayers& p) {
  PlateJobOptions o;
  o.slicing = slice_options(p.layer_thickness, p.z_start);
  o.slicing.encoding = false;
  o.strict = p.strict;
  // A range of layers holds at most a quarter of the memory still available, so a job leaves
  // room for its masks and for other jobs.
  o.memory_share = 0.25;
  return o;
}

}  // namespace slicereuse::plugin
