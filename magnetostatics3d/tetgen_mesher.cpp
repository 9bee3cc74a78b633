// TetGen (AGPL-3.0, Debian libtet1.5-dev) behind the Plc -> TetMesh interface.
#define TETLIBRARY
#include <tetgen.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "magnetostatics3d/plc.hpp"

namespace rheomag::magnetostatics3d {
namespace {

std::string tetgen_error(int code) {
  switch (code) {
    case 1:
      return "out of memory";
    case 2:
      return "internal error (please report)";
    case 3:
      return "a self-intersection of the input facets";
    case 4:
      return "a very small input feature size (facets or points nearly touching)";
    case 5:
      return "two very close input facets";
    case 10:
      return "an input error";
    default:
      return "error code " + std::to_string(code);
  }
}

/// TetGen's output arrays, as sent from the meshing child process.
struct MeshArrays {
  std::vector<double> points;      // 3 per point
  std::vector<int> tets;           // 4 per tetrahedron
  std::vector<double> attributes;  // region attribute per tetrahedron (0: none)
  std::vector<int> faces;          // 3 per boundary or facet face
  std::vector<int> marker;         // facet marker per face
};

template <class T>
bool send_array(int fd, const T* data, std::size_t count) {
  const std::size_t bytes = count * sizeof(T);
  if (write(fd, &count, sizeof count) != static_cast<ssize_t>(sizeof count)) return false;
  const char* p = reinterpret_cast<const char*>(data);
  for (std::size_t done = 0; done < bytes;) {
    const ssize_t n = write(fd, p + done, bytes - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

bool send_mesh(int fd, const tetgenio& out) {
  std::vector<int> tets(4 * static_cast<std::size_t>(out.numberoftetrahedra));
  std::vector<double> attributes(out.numberoftetrahedra, 0.0);
  for (int t = 0; t < out.numberoftetrahedra; ++t) {
    for (int k = 0; k < 4; ++k) tets[4 * t + k] = out.tetrahedronlist[out.numberofcorners * t + k];
    if (out.numberoftetrahedronattributes > 0)
      attributes[t] = out.tetrahedronattributelist[out.numberoftetrahedronattributes * t];
  }
  std::vector<int> marker(out.numberoftrifaces, 0);
  for (int f = 0; f < out.numberoftrifaces && out.trifacemarkerlist; ++f)
    marker[f] = out.trifacemarkerlist[f];
  return send_array(fd, out.pointlist, 3 * static_cast<std::size_t>(out.numberofpoints)) &&
         send_array(fd, tets.data(), tets.size()) &&
         send_array(fd, attributes.data(), attributes.size()) &&
         send_array(fd, out.trifacelist, 3 * static_cast<std::size_t>(out.numberoftrifaces)) &&
         send_array(fd, marker.data(), marker.size());
}

template <class T>
std::vector<T> receive_array(const std::vector<char>& bytes, std::size_t& at) {
  std::size_t count = 0;
  if (at + sizeof count > bytes.size()) throw InputError("tetrahedral mesher: truncated output");
  std::memcpy(&count, bytes.data() + at, sizeof count);
  at += sizeof count;
  if (count > (bytes.size() - at) / sizeof(T))
    throw InputError("tetrahedral mesher: truncated output");
  std::vector<T> values(count);
  std::memcpy(values.data(), bytes.data() + at, count * sizeof(T));
  at += count * sizeof(T);
  return values;
}

MeshArrays receive_mesh(const std::vector<char>& bytes) {
  MeshArrays m;
  std::size_t at = 0;
  m.points = receive_array<double>(bytes, at);
  m.tets = receive_array<int>(bytes, at);
  m.attributes = receive_array<double>(bytes, at);
  m.faces = receive_array<int>(bytes, at);
  m.marker = receive_array<int>(bytes, at);
  return m;
}

}  // namespace

TetMesh tetrahedralize(const Plc& plc, const TetMeshOptions& options) {
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(plc.points.size());
  in.pointlist = new REAL[3 * plc.points.size()];
  for (std::size_t i = 0; i < plc.points.size(); ++i) {
    for (int k = 0; k < 3; ++k) in.pointlist[3 * i + k] = plc.points[i][k];
  }
  in.numberoffacets = static_cast<int>(plc.facets.size());
  in.facetlist = new tetgenio::facet[plc.facets.size()];
  in.facetmarkerlist = new int[plc.facets.size()];
  for (std::size_t f = 0; f < plc.facets.size(); ++f) {
    tetgenio::facet& facet = in.facetlist[f];
    tetgenio::init(&facet);
    const auto& polygons = plc.facets[f].polygons;
    facet.numberofpolygons = static_cast<int>(polygons.size());
    facet.polygonlist = new tetgenio::polygon[polygons.size()];
    for (std::size_t p = 0; p < polygons.size(); ++p) {
      tetgenio::polygon& poly = facet.polygonlist[p];
      tetgenio::init(&poly);
      poly.numberofvertices = static_cast<int>(polygons[p].size());
      poly.vertexlist = new int[polygons[p].size()];
      for (std::size_t v = 0; v < polygons[p].size(); ++v) poly.vertexlist[v] = polygons[p][v];
    }
    in.facetmarkerlist[f] = static_cast<int>(plc.facets[f].kind);
  }
  in.numberofregions = static_cast<int>(plc.regions.size());
  in.regionlist = new REAL[5 * plc.regions.size()];
  for (std::size_t r = 0; r < plc.regions.size(); ++r) {
    for (int k = 0; k < 3; ++k) in.regionlist[5 * r + k] = plc.regions[r].point[k];
    in.regionlist[5 * r + 3] = plc.regions[r].region + 1;  // attribute 0 = no seed reached it
    in.regionlist[5 * r + 4] = plc.regions[r].max_volume > 0 ? plc.regions[r].max_volume : -1.0;
  }
  in.numberofholes = static_cast<int>(plc.holes.size());
  in.holelist = new REAL[3 * plc.holes.size() + 1];
  for (std::size_t h = 0; h < plc.holes.size(); ++h) {
    for (int k = 0; k < 3; ++k) in.holelist[3 * h + k] = plc.holes[h][k];
  }

  // p: PLC; q: quality; A: region attributes; a: region volume limits; Q: quiet; z: from 0.
  char switches[96];
  std::snprintf(switches, sizeof switches, "pq%g/%gAaQz", options.radius_edge_ratio,
                options.min_dihedral);
  // TetGen 1.5.0 frees its memory pools twice when it stops on bad input (terminatetetgen
  // frees them, then the unwinding destructor again): the process crashes instead of throwing.
  // So it runs in a child process that sends the mesh back through a pipe; a child that dies
  // or exits non-zero is a TetGen failure of the input.
  int channel[2];
  if (pipe(channel) != 0) throw InputError(plc.source + ": cannot start the tetrahedral mesher");
  std::fflush(nullptr);
  // A worker process: killed with rheomag when it is interrupted (core/interrupt.hpp).
  const pid_t child = fork_worker_process();
  if (child < 0) throw InputError(plc.source + ": cannot start the tetrahedral mesher");
  if (child == 0) {
    close(channel[0]);
    int code = 0;
    try {
      ::tetrahedralize(switches, &in, &out);
    } catch (int c) {
      code = c;
    }
    if (code == 0) code = send_mesh(channel[1], out) ? 0 : 99;
    _exit(code);
  }
  close(channel[1]);
  std::vector<char> bytes;
  char buffer[1 << 16];
  for (ssize_t n; (n = read(channel[0], buffer, sizeof buffer)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    bytes.insert(bytes.end(), buffer, buffer + n);
  }
  close(channel[0]);
  int status = 0;
  while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
  }
  release_worker_process(child);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw InputError(plc.source + ": the tetrahedral mesher (TetGen) failed: " +
                     (WIFEXITED(status) ? tetgen_error(WEXITSTATUS(status))
                                        : "it stopped on the input (self-intersecting or nearly "
                                          "touching facets)"));
  }
  const MeshArrays mesh_arrays = receive_mesh(bytes);

  TetMesh mesh;
  const std::size_t n_points = mesh_arrays.points.size() / 3;
  mesh.nodes.resize(n_points);
  for (std::size_t i = 0; i < n_points; ++i) {
    mesh.nodes[i] = {mesh_arrays.points[3 * i], mesh_arrays.points[3 * i + 1],
                     mesh_arrays.points[3 * i + 2]};
  }
  const std::size_t n_tets = mesh_arrays.tets.size() / 4;
  mesh.tets.resize(n_tets);
  mesh.region.resize(n_tets);
  for (std::size_t t = 0; t < n_tets; ++t) {
    for (int k = 0; k < 4; ++k) mesh.tets[t][k] = mesh_arrays.tets[4 * t + k];
    const int attribute = static_cast<int>(mesh_arrays.attributes[t]);
    mesh.region[t] = attribute > 0 ? attribute - 1 : plc.default_region;
    if (mesh.region[t] < 0) {
      throw InputError(plc.source + ": a part of the 3D domain belongs to no region");
    }
    if (mesh.volume(static_cast<int>(t)) < 0) std::swap(mesh.tets[t][2], mesh.tets[t][3]);
  }
  for (std::size_t f = 0; f < mesh_arrays.marker.size(); ++f) {
    const int marker = mesh_arrays.marker[f];
    if (marker != static_cast<int>(FaceKind::outer) &&
        marker != static_cast<int>(FaceKind::symmetry))
      continue;
    mesh.faces.push_back(
        {mesh_arrays.faces[3 * f], mesh_arrays.faces[3 * f + 1], mesh_arrays.faces[3 * f + 2]});
    mesh.face_kind.push_back(static_cast<FaceKind>(marker));
  }
  mesh.build_edges();
  return mesh;
}

}  // namespace rheomag::magnetostatics3d
