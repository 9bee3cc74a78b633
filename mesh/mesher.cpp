// Quality triangulation of a PSLG (see mesher.hpp).

#include "mesh/mesher.hpp"

#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesher_2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>
#include <sstream>
#include <string>
#include <unordered_map>

#include "core/error.hpp"
#include "core/memory_limit.hpp"
#include "mesh/elevate.hpp"
#include "mesh/initial_points.hpp"
#include "mesh/pslg_check.hpp"
#include "mesh/region_labels.hpp"
#include "mesh/size_field.hpp"

namespace rheomag::mesh {

double solve_bytes_per_triangle(int order) {
  // 1.14 GiB / 1e6 unknowns = 1.2 kB per unknown; P2 has about 2 unknowns per triangle, P1 about
  // 1/2; half as much again for the mesher's own structures and the results.
  return order == 1 ? 900.0 : 3600.0;
}

namespace {

using detail::Cdt;
using detail::CgalPoint;
using detail::SizeField;

/// CGAL's shape and size criteria with the size bound taken from a SizeField at the centroid of
/// each face: a face is bad when its longest edge exceeds h(centroid) or its smallest angle is
/// below the bound (CGAL's B = sin^2 of that angle).
class SizeFieldCriteria : public CGAL::Delaunay_mesh_size_criteria_2<Cdt> {
 public:
  using Base = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
  using Quality = Base::Quality;

  SizeFieldCriteria(double shape_bound, std::shared_ptr<const SizeField> field)
      : CGAL::Delaunay_mesh_criteria_2<Cdt>(shape_bound),
        Base(shape_bound, 0.0),
        field_(std::move(field)) {}

  /// The face test used by CGAL's Delaunay_mesher_2.
  class Is_bad : public Base::Is_bad {
   public:
    Is_bad(double shape_bound, const Geom_traits& traits, const SizeField* field)
        : Base::Is_bad(shape_bound, 0.0, traits), field_(field) {}

    using Base::Is_bad::operator();

    CGAL::Mesh_2::Face_badness operator()(const Cdt::Face_handle& fh, Quality& q) const {
      const CgalPoint& pa = fh->vertex(0)->point();
      const CgalPoint& pb = fh->vertex(1)->point();
      const CgalPoint& pc = fh->vertex(2)->point();
      const double a = CGAL::squared_distance(pb, pc);
      const double b = CGAL::squared_distance(pc, pa);
      const double c = CGAL::squared_distance(pa, pb);
      const double longest = std::max({a, b, c});
      const double h = field_->at(CGAL::centroid(pa, pb, pc));
      q.second = longest / (h * h);
      if (q.size() > 1.0) {
        q.first = 1.0;  // too large: the angle is not needed
        return CGAL::Mesh_2::IMPERATIVELY_BAD;
      }
      const double middle = a + b + c - longest - std::min({a, b, c});
      const double twice_area = 2.0 * CGAL::area(pa, pb, pc);
      q.first = twice_area * twice_area / (longest * middle);  // sin^2 of the smallest angle
      return q.sine() < this->B ? CGAL::Mesh_2::BAD : CGAL::Mesh_2::NOT_BAD;
    }

   private:
    const SizeField* field_;
  };

  Is_bad is_bad_object() const { return Is_bad(this->bound(), this->traits, field_.get()); }

 private:
  std::shared_ptr<const SizeField> field_;
};

void check_options(const Pslg& pslg, const MeshOptions& options) {
  const std::string name = pslg_name(pslg) + ": mesh option ";
  if (options.order != 1 && options.order != 2)
    throw InputError(name + "order = " + std::to_string(options.order) + "; expected 1 or 2");
  if (!(options.min_angle > 0.0 && options.min_angle <= 30.0))
    throw InputError(name + "min_angle = " + format_number(options.min_angle) +
                     " deg; expected (0, 30] (CGAL's refinement is guaranteed to end up to "
                     "about 20.7 deg)");
  if (!(std::isfinite(options.default_size) && options.default_size >= 0.0))
    throw InputError(name + "default_size = " + format_number(options.default_size) +
                     "; expected a length >= 0 (0 = automatic)");
  if (!(std::isfinite(options.size_scale) && options.size_scale > 0.0))
    throw InputError(name + "size_scale = " + format_number(options.size_scale) +
                     "; expected a factor > 0");
  if (options.min_gap_elements < 1)
    throw InputError(name + "min_gap_elements = " + std::to_string(options.min_gap_elements) +
                     "; expected >= 1");
  if (!(std::isfinite(options.grading) && options.grading >= 0.0))
    throw InputError(name + "grading = " + format_number(options.grading) + "; expected >= 0");
}

/// Target edge length of each region: its mesh_size or the default, at most
/// thickness / min_gap_elements in a fluid gap; infinite for holes.
std::vector<double> region_sizes(const Pslg& pslg, const MeshOptions& options,
                                 const std::vector<detail::RegionGeometry>& geometry,
                                 double default_size) {
  std::vector<double> size(pslg.regions.size());
  for (std::size_t r = 0; r < pslg.regions.size(); ++r) {
    const RegionSeed& region = pslg.regions[r];
    if (region.hole) {
      size[r] = std::numeric_limits<double>::infinity();
      continue;
    }
    size[r] = region.mesh_size > 0.0 ? region.mesh_size : default_size;
    if (region.gap != GapKind::none)
      size[r] = std::min(size[r], geometry[r].thickness / options.min_gap_elements);
    size[r] *= options.size_scale;
  }
  return size;
}

/// Refuses meshes whose estimated element count exceeds options.max_elements, or whose solve
/// would need more than options.max_memory; returns the estimate (triangles).
double check_mesh_size(const Pslg& pslg, const MeshOptions& options,
                       const std::vector<detail::RegionGeometry>& geometry,
                       const std::vector<double>& size) {
  // Equilateral triangles of edge h have area sqrt(3)/4 h^2; refined meshes are about twice as
  // dense, hence the factor 2.
  double estimate = 0.0;
  std::size_t smallest = size.size();
  for (std::size_t r = 0; r < size.size(); ++r)
    if (std::isfinite(size[r]) && size[r] > 0.0) {
      estimate += 2.0 * geometry[r].area / (std::sqrt(3.0) / 4.0 * size[r] * size[r]);
      if (smallest == size.size() || size[r] < size[smallest]) smallest = r;
    }
  // Boundaries cut finer than their regions: about two triangles per piece beside them.
  double segment_pieces = 0.0;
  for (const Segment& s : pslg.segments) {
    if (!(s.max_length > 0.0)) continue;
    const Point& a = pslg.points[static_cast<std::size_t>(s.a)];
    const Point& b = pslg.points[static_cast<std::size_t>(s.b)];
    segment_pieces += std::hypot(b.r - a.r, b.z - a.z) / s.max_length;
  }
  estimate += 2.0 * segment_pieces;
  if (options.max_elements <= 0) return estimate;
  const double max_memory = options.max_memory > 0.0 ? options.max_memory : default_memory_limit();
  const double bytes = estimate * solve_bytes_per_triangle(options.order);
  if (estimate > static_cast<double>(options.max_elements) || bytes > max_memory) {
    // The sizes are in metres here whatever the input's units: say the smallest one so a unit
    // mistake shows (a case in mm converts its mesh_size to metres before it reaches the mesher).
    std::ostringstream smallest_size, count;
    smallest_size << size[smallest] << " m in region '" << pslg.regions[smallest].name << "'";
    if (segment_pieces > 0.5 * estimate / 2.0)
      smallest_size << "; the boundaries' own maximum lengths cut them into about "
                    << segment_pieces << " pieces";
    // Three digits of a double: a size off by many orders of magnitude gives more elements than
    // any integer type holds (a cast printed -9223372036854775808).
    count.precision(3);
    count << estimate;
    const bool too_many = estimate > static_cast<double>(options.max_elements);
    throw InputError(
        pslg_name(pslg) + ": the requested mesh sizes give about " + count.str() + " elements" +
        (too_many ? ", more than the " + std::to_string(options.max_elements) + " allowed"
                  : " whose solve would need about " + memory_size_text(bytes) +
                        ", more than the " + memory_size_text(max_memory) +
                        " allowed (--max-memory; default 3/4 of the memory available: physical, "
                        "ulimit -v, cgroup)") +
        "; expected larger mesh sizes (the smallest is " + smallest_size.str() + ")");
  }
  return estimate;
}

double automatic_size(const Cdt& cdt) {
  double r_lo = std::numeric_limits<double>::infinity(), r_hi = -r_lo, z_lo = r_lo, z_hi = -r_lo;
  for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
    r_lo = std::min(r_lo, v->point().x()), r_hi = std::max(r_hi, v->point().x());
    z_lo = std::min(z_lo, v->point().y()), z_hi = std::max(z_hi, v->point().y());
  }
  return std::max(r_hi - r_lo, z_hi - z_lo) / 30.0;
}

/// Boundary marker of the coarse constrained edge that contains point m (a midpoint of a fine
/// constrained edge): the nearest constrained edge of the located face and its neighbours. The
/// neighbours matter where m, rounded, falls just beside its edge: outside the convex hull
/// (an infinite face) or in the sliver that a nearly collinear split point makes.
int marker_at(const Cdt& coarse, const CgalPoint& m, Cdt::Face_handle& hint) {
  hint = coarse.locate(m, hint);
  int best_marker = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](const Cdt::Face_handle& f) {
    if (coarse.is_infinite(f)) return;
    for (int i = 0; i < 3; ++i) {
      if (!coarse.is_constrained({f, i})) continue;
      const CgalPoint& a = f->vertex(Cdt::ccw(i))->point();
      const CgalPoint& b = f->vertex(Cdt::cw(i))->point();
      const double d = CGAL::squared_distance(m, Cdt::Geom_traits::Segment_2(a, b));
      if (d < best_distance) best_distance = d, best_marker = f->info().boundary[i];
    }
  };
  consider(hint);
  for (int i = 0; i < 3; ++i) consider(hint->neighbor(i));
  if (coarse.is_infinite(hint)) hint = hint->neighbor(hint->index(coarse.infinite_vertex()));
  return best_marker;
}

/// Copies the refined in-domain faces of `fine` into a linear Mesh.
Mesh extract_mesh(const Cdt& fine, const Cdt& coarse, const SizeField& field) {
  Mesh mesh;
  std::unordered_map<Cdt::Vertex_handle, int> index_of;
  for (auto f = fine.finite_faces_begin(); f != fine.finite_faces_end(); ++f)
    if (f->is_in_domain())
      for (int i = 0; i < 3; ++i) index_of.emplace(f->vertex(i), -1);
  // Nodes in the triangulation's own (deterministic) vertex order.
  for (auto v = fine.finite_vertices_begin(); v != fine.finite_vertices_end(); ++v) {
    auto it = index_of.find(v);
    if (it == index_of.end()) continue;
    it->second = static_cast<int>(mesh.nodes.size());
    mesh.nodes.push_back({v->point().x(), v->point().y()});
  }
  for (auto f = fine.finite_faces_begin(); f != fine.finite_faces_end(); ++f) {
    if (!f->is_in_domain()) continue;
    std::array<int, 6> t{-1, -1, -1, -1, -1, -1};
    for (int i = 0; i < 3; ++i) t[static_cast<std::size_t>(i)] = index_of.at(f->vertex(i));
    mesh.triangles.push_back(t);
    mesh.region.push_back(field.region_at(
        CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point())));
  }
  Cdt::Face_handle hint = coarse.finite_faces_begin();
  for (auto e = fine.finite_edges_begin(); e != fine.finite_edges_end(); ++e) {
    if (!fine.is_constrained(*e)) continue;
    auto [f, i] = *e;
    if (!f->is_in_domain() || fine.is_infinite(f)) {
      const Cdt::Face_handle n = f->neighbor(i);
      i = n->index(f);
      f = n;
      if (!f->is_in_domain() || fine.is_infinite(f)) continue;
    }
    const CgalPoint& a = f->vertex(Cdt::ccw(i))->point();
    const CgalPoint& b = f->vertex(Cdt::cw(i))->point();
    const int marker = marker_at(coarse, CGAL::midpoint(a, b), hint);
    if (marker < 0) continue;
    // Nodes in the counter-clockwise order of the meshed face: domain on the left.
    mesh.boundary_edges.push_back(
        {{index_of.at(f->vertex(Cdt::ccw(i))), index_of.at(f->vertex(Cdt::cw(i))), -1}, marker});
  }
  mesh.vertex_count = static_cast<int>(mesh.nodes.size());
  return mesh;
}

}  // namespace

Mesh generate_mesh(const Pslg& pslg, const MeshOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  // Progress: triangles made (twice the vertices) of the estimate, timed from the start.
  double estimate = 0.0;
  const auto report = [&](const char* stage, double done) {
    if (!options.progress) return;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    // The estimate counts the requested sizes, not the refinement that small features force:
    // past it, the total is unknown (no count, no time left) rather than "800000 of 1632".
    options.progress({stage, done, done <= estimate ? estimate : 0.0, elapsed.count(), "", false});
  };
  check_options(pslg, options);
  const PreparedPslg prepared = prepare_pslg(pslg);

  Cdt coarse;
  detail::insert_pslg(prepared, coarse);
  detail::label_regions(pslg, coarse);
  const int region_count = static_cast<int>(pslg.regions.size());
  const auto geometry = detail::region_geometry(coarse, region_count);

  const double default_size =
      options.default_size > 0.0 ? options.default_size : automatic_size(coarse);
  std::vector<double> size = region_sizes(pslg, options, geometry, default_size);
  estimate = check_mesh_size(pslg, options, geometry, size);
  report("geometry checked", 0.0);
  // The size sources are taken, and regions located, in the PSLG with its segments whole: a
  // segment cut into thousands of pieces fans the coarse triangulation into slivers that every
  // point location walked through (a 10 mm segment in 10^4 pieces: 37 s to mesh, now 1.3 s).
  // A boundary of many real vertices (a finely divided arc) is refined for shape before it is
  // searched (detail::RegionLocator; an arc in 0.01 degree steps: 3.4 s, now 0.9 s).
  Cdt outline;
  detail::insert_pslg(prepared, outline, detail::SegmentPieces::whole);
  detail::label_regions(pslg, outline);
  auto field = std::make_shared<const SizeField>(outline, pslg, size, options.grading);

  Cdt fine = coarse;
  // Start from a lattice at the target sizes: the refinement then only repairs the boundary
  // layers and graded zones instead of growing every region from its corners.
  Cdt::Face_handle hint;
  for (const CgalPoint& p : detail::lattice_points(coarse, size, *field)) {
    hint = fine.insert(p, hint)->face();
    if (fine.number_of_vertices() % 20000 == 0)
      report("inserting the lattice", 2.0 * static_cast<double>(fine.number_of_vertices()));
  }
  bool anything_to_mesh = false;
  for (auto f = fine.all_faces_begin(); f != fine.all_faces_end(); ++f) {
    bool meshed = false;
    if (!fine.is_infinite(f)) {
      const int r = field->region_at(
          CGAL::centroid(f->vertex(0)->point(), f->vertex(1)->point(), f->vertex(2)->point()));
      meshed = r >= 0 && !pslg.regions[static_cast<std::size_t>(r)].hole;
    }
    f->set_in_domain(meshed);
    anything_to_mesh = anything_to_mesh || meshed;
  }
  if (!anything_to_mesh)
    throw InputError(pslg_name(pslg) + ": every region is a hole; expected something to mesh");

  const double angle = options.min_angle * std::numbers::pi / 180.0;
  const double shape_bound = std::sin(angle) * std::sin(angle);
  CGAL::Delaunay_mesher_2<Cdt, SizeFieldCriteria> mesher(fine,
                                                         SizeFieldCriteria(shape_bound, field));
  mesher.init(/*domain_specified=*/true);
  if (options.progress) {
    // One step at a time (the order refine_mesh takes), reporting every 20 000 points.
    const auto made = [&fine] { return 2.0 * static_cast<double>(fine.number_of_vertices()); };
    report("refining", made());
    for (long step = 1; mesher.try_one_step_refine_mesh(); ++step)
      if (step % 20000 == 0) report("refining", made());
    report("refined", made());
  } else {
    mesher.refine_mesh();
  }

  Mesh mesh = extract_mesh(fine, coarse, *field);
  return options.order == 2 ? elevate_to_p2(mesh) : mesh;
}

}  // namespace rheomag::mesh
