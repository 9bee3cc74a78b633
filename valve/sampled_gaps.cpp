// Gap sampling (sampled_gaps.hpp): geometry from the gap rectangle in the meridian plane
// (GapResult mid-line and area); |B_n| (B_r annular, B_z radial) at kSamples mid-line points
// (cell centres of a uniform split).

#include "valve/sampled_gaps.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"

namespace rheomag::valve {

namespace {

constexpr int kSamples = 101;

fluid::GapFieldSamples sample_gap(const magnetostatics::MagnetostaticSolver& solver,
                                  const magnetostatics::Solution& solution,
                                  const magnetostatics::GapResult& gap, double start_offset) {
  fluid::GapFieldSamples field;
  const double dr = gap.line_end.r - gap.line_start.r, dz = gap.line_end.z - gap.line_start.z;
  const double length = std::hypot(dr, dz);
  const bool annular = gap.kind == mesh::GapKind::annular;
  for (int i = 0; i < kSamples; ++i) {
    const double t = (i + 0.5) / kSamples;
    const mesh::Point p{gap.line_start.r + t * dr, gap.line_start.z + t * dz};
    std::array<double, 2> b{};
    if (!magnetostatics::flux_density_at(solver, solution, p, gap.region, b)) continue;
    const double position = annular ? t * length : p.r;
    if (!annular && position < start_offset) continue;
    field.position.push_back(position);
    field.b.push_back(std::abs(annular ? b[0] : b[1]));
  }
  if (field.position.size() < 2)
    throw InputError("gap \"" + gap.name + "\": fewer than 2 mid-line field samples found");
  return field;
}

}  // namespace

std::vector<SampledGap> sample_gaps(const magnetostatics::MagnetostaticSolver& solver,
                                    const magnetostatics::Solution& solution,
                                    const magnetostatics::Results& results, double inlet_radius,
                                    const std::string& inlet_key) {
  std::vector<SampledGap> gaps;
  for (const auto& result : results.gaps) {
    SampledGap gap;
    gap.name = result.name;
    gap.annular = result.kind == mesh::GapKind::annular;
    gap.field = sample_gap(solver, solution, result, gap.annular ? 0.0 : inlet_radius);
    const double dr = std::abs(result.line_end.r - result.line_start.r);
    const double dz = std::abs(result.line_end.z - result.line_start.z);
    if (gap.annular) {
      gap.annulus = fluid::AnnulusGeometry{result.area / dz, result.line_start.r, dz};
    } else {
      const double r_in = std::max(std::min(result.line_start.r, result.line_end.r), inlet_radius);
      const double r_out = std::max(result.line_start.r, result.line_end.r);
      if (!(r_in > 0.0))
        throw InputError("gap \"" + result.name + "\" starts on the axis: set " + inlet_key +
                         " (m) to the radius where it begins");
      gap.radial = fluid::RadialGeometry{result.area / dr, r_in, r_out};
    }
    gaps.push_back(std::move(gap));
  }
  return gaps;
}

void zero_fields(std::vector<SampledGap>& gaps) {
  for (SampledGap& gap : gaps) std::fill(gap.field.b.begin(), gap.field.b.end(), 0.0);
}

}  // namespace rheomag::valve
