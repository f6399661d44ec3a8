// Reading member mesh files (read_mesh_file, slicereuse/formats/mesh_file.h): the family's base
// written as binary STL, ASCII STL, binary PLY (float x y z, uchar/int faces), ASCII PLY and
// OBJ, each read --runs times; prints per format the file size, the median seconds and the faces
// per second. The files stay in --out (default /tmp/slicereuse-bench) so that pymeshlab's
// load_new_mesh can be timed on the same files. Reads follow writes, so they are served from the
// page cache: the figures measure parsing, not the disk.
// Usage: bench_mesh_files [--shape S] [--faces N] [--runs R] [--out DIR]
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_args.h"
#include "mesh_file_writers.h"
#include "slicereuse/formats/mesh_file.h"

using namespace slicereuse;

int main(int argc, char** argv) {
  const BenchArgs args = parse_bench_args(argc, argv);
  std::filesystem::create_directories(args.out);
  const Mesh base = test::make_family_base(args.family);
  std::printf("shape %s, %zu vertices, %zu faces, median of %d runs\n", args.family.shape.c_str(), base.vertices(),
              base.faces(), args.runs);
  std::printf("%-11s %10s %10s %14s  %s\n", "format", "MB", "seconds", "faces/s", "file");
  using test::MeshFileKind;
  for (MeshFileKind kind : {MeshFileKind::StlBinary, MeshFileKind::StlAscii, MeshFileKind::PlyBinary,
                            MeshFileKind::PlyAscii, MeshFileKind::Obj}) {
    const std::string name = test::mesh_file_kind_name(kind);
    std::string stem = name;
    for (char& c : stem) c = c == ' ' ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
    const std::string path = args.out + "/mesh_files_" + stem + test::mesh_file_extension(kind);
    test::write_mesh_file(path, base, kind);
    std::vector<double> seconds;
    size_t faces = 0;
    for (int r = 0; r < args.runs; ++r) {
      const auto t0 = std::chrono::steady_clock::now();
      const Mesh m = read_mesh_file(path);
      seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
      faces = m.faces();
    }
    const double s = median_of(seconds);
    std::printf("%-11s %10.1f %10.4f %14.0f  %s\n", name.c_str(), double(std::filesystem::file_size(path)) / 1e6, s,
                double(faces) / s, path.c_str());
  }
}
