// lightlab_subdivide IN OUT LEVELS -- Loop-subdivides a triangle mesh with
// OpenMesh (each level multiplies the triangle count by 4) and writes it as
// binary PLY. The build makes the larger bunnies for the speed work with it.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Tools/Subdivider/Uniform/LoopT.hh>

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: lightlab_subdivide IN OUT LEVELS\n");
    return 2;
  }
  const int levels = std::atoi(argv[3]);
  if (levels < 0 || levels > 6) {
    std::fprintf(stderr, "lightlab_subdivide: LEVELS must be in [0, 6], got %s\n", argv[3]);
    return 2;
  }
  using Mesh = OpenMesh::TriMesh_ArrayKernelT<>;
  Mesh mesh;
  if (!OpenMesh::IO::read_mesh(mesh, argv[1])) {
    std::fprintf(stderr, "lightlab_subdivide: cannot read mesh %s\n", argv[1]);
    return 2;
  }
  OpenMesh::Subdivider::Uniform::LoopT<Mesh> loop;
  loop.attach(mesh);
  loop(static_cast<size_t>(levels));
  loop.detach();
  OpenMesh::IO::Options binary(OpenMesh::IO::Options::Binary);
  if (!OpenMesh::IO::write_mesh(mesh, argv[2], binary)) {
    std::fprintf(stderr, "lightlab_subdivide: cannot write %s\n", argv[2]);
    return 2;
  }
  std::printf("%s: %zu triangles, %zu vertices\n", argv[2], mesh.n_faces(), mesh.n_vertices());
  return 0;
}
