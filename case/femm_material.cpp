// A FEMM block property as the Material FEMM's magnetostatic solver uses (see femm_material.hpp).

#include "case/femm_material.hpp"

#include <algorithm>
#include <cmath>

#include "case/femm_bh_smoothing.hpp"
#include "case/material_library.hpp"
#include "case/toml_section.hpp"
#include "core/constants.hpp"

namespace rheomag::cases::femm {

std::array<double, 2> linear_femm_permeability(
    int lam_type, double fill, double mu_x, double mu_y,
    const std::function<void(const std::string&)>& fail) {
  // Only the permeability along the laminations counts for LamType 1 (Mu_x) and 2 (Mu_y).
  const bool uses_x = lam_type != 2, uses_y = lam_type != 1;
  if (uses_x && !(mu_x > 0.0 && std::isfinite(mu_x)))
    fail("Mu_x = " + format_number(mu_x) + "; expected a finite relative permeability > 0");
  if (uses_y && !(mu_y > 0.0 && std::isfinite(mu_y)))
    fail("Mu_y = " + format_number(mu_y) + "; expected a finite relative permeability > 0");
  const auto along = [fill](double mu) { return fill * mu + (1.0 - fill); };          // parallel
  const auto across = [fill](double mu) { return mu / (fill + mu * (1.0 - fill)); };  // series
  if (lam_type == 1) return {along(mu_x), across(mu_x)};
  if (lam_type == 2) return {across(mu_y), along(mu_y)};
  return {along(mu_x), along(mu_y)};  // in-plane laminations (LamType 0) or none
}

std::string axisymmetric_lamination_note(const FemBlock& block, const std::string& where) {
  const double f = block.lam_fill;
  if (!block.bh.empty() || !(f < 1.0) || (block.lam_type != 0 && block.lam_type != 2)) return "";
  const auto pair = [](double r, double z) {
    return "mu_r " + format_number(r) + " along r, " + format_number(z) + " along z";
  };
  const std::string head = where + ": block '" + block.name + "': LamType " +
                           std::to_string(block.lam_type) + " at LamFill " + format_number(f) +
                           " in an axisymmetric model: ";
  if (block.lam_type == 2) {
    const double along = f * block.mu_y + 1.0 - f, across = block.mu_y / (f + block.mu_y * (1 - f));
    return head + "FEMM's axisymmetric solver (xfemm 35baec4) laminates a linear block of " +
           "LamType 2 along r, as LamType 1 (" + pair(along, across) +
           "); rheomag laminates it along z, as FEMM's manual and planar solver do (" +
           pair(across, along) + ")";
  }
  const double femm_r = f * block.mu_x, femm_z = f * block.mu_y;
  const double r = femm_r + 1.0 - f, z = femm_z + 1.0 - f;
  if ((1.0 - f) <= 1e-3 * std::min(femm_r, femm_z)) return "";
  return head + "FEMM's axisymmetric solver (xfemm 35baec4) takes f Mu (" + pair(femm_r, femm_z) +
         "), its planar solver and rheomag f Mu + 1 - f (" + pair(r, z) + ")";
}

Material femm_material(const FemBlock& block, const std::string& source, const FemReader& reader,
                       std::vector<std::string>& warnings) {
  const std::string name = "block '" + block.name + "'";
  auto fail = [&](const std::string& message) { reader.fail(block.line, name + ": " + message); };
  Material m;
  m.name = block.name;
  m.source = "FEMM file " + source + ", block '" + block.name + "'";
  // A negative conductivity would make the transient solver's eddy currents grow without bound.
  if (!(block.sigma >= 0.0))
    fail("Sigma = " + format_number(block.sigma) + " MS/m; expected a conductivity >= 0");
  m.conductivity = block.sigma * 1e6;  // MS/m -> S/m (kept for eddy-current work)
  const double fill = block.lam_fill;
  if (!(fill > 0.0 && fill <= 1.0))
    fail("LamFill = " + format_number(fill) + "; expected a fill factor in (0, 1]");
  if (block.lam_type < 0 || block.lam_type > 6)
    fail("unknown LamType " + std::to_string(block.lam_type));
  if (block.h_c_angle != 0.0)
    fail("H_cAngle = " + format_number(block.h_c_angle) +
         " is not supported; give the magnetisation direction in the block label");
  if (block.lam_type >= 3) {
    // Wire (magnet, stranded, litz, square): FEMM's magnetostatic solver sets mu_r = 1 and
    // ignores the B-H curve; the winding's fill matters only at a frequency > 0.
    if (block.h_c != 0.0) fail("a wire block (LamType >= 3) cannot be a magnet (H_c not 0)");
    m.mu_r = 1.0;
    m.source += " (wire, LamType " + std::to_string(block.lam_type) + ": mu_r = 1 as in FEMM)";
    return m;
  }
  if (!block.bh.empty()) {
    if ((block.lam_type == 1 || block.lam_type == 2) && fill != 1.0)
      fail("a B-H table laminated along " + std::string(block.lam_type == 1 ? "x" : "y") +
           " (LamType " + std::to_string(block.lam_type) +
           ") with LamFill < 1 is a nonlinear anisotropic material, which is not supported; "
           "a linear one (BHPoints = 0) is");
    // FEMM smooths a table whose spline turns back (femm_bh_smoothing.hpp), then applies the
    // fill of in-plane laminations (LamType 0), B' = f B(H) + (1 - f) mu0 H at the table's H
    // (FEMM's apparent curve), and checks the result again.
    const std::string where = source + ":" + std::to_string(block.line) + ": " + name;
    FemmSmoothedTable smoothed = femm_smoothed_bh_table(block.bh);
    int passes = smoothed.passes;
    if (fill != 1.0) {
      for (auto& [b, h] : smoothed.points) b = fill * b + (1.0 - fill) * kMu0 * h;
      smoothed = femm_smoothed_bh_table(std::move(smoothed.points));
      passes += smoothed.passes;
    }
    if (passes > 0) {
      std::string what = "the spline FEMM fits through the B-H table turns back (dH/dB < 0)";
      for (std::size_t i = 1; i < block.bh.size(); ++i)
        if (!(block.bh[i].first > block.bh[i - 1].first &&
              block.bh[i].second > block.bh[i - 1].second)) {
          what = "the B-H table does not increase at point " + std::to_string(i + 1) + " [" +
                 format_number(block.bh[i].first) + ", " + format_number(block.bh[i].second) + "]";
          break;
        }
      const std::string count = std::to_string(passes) + (passes == 1 ? " pass" : " passes");
      warnings.push_back(where + ": " + what +
                         "; smoothed as FEMM does: every interior point averaged with its two "
                         "neighbours, " +
                         count + ", until FEMM's spline rises throughout");
      m.source += " (B-H table smoothed as FEMM does, " + count + ")";
    }
    m.bh = checked_bh_table(smoothed.points, where);
    m.bh_interpolation = BhInterpolation::femm_natural_spline;
    // A nonlinear magnet: FEMM's table is the magnet's curve shifted by H_c to start at (0, 0),
    // H = H_curve(|B|) B/|B| - H_c m; the magnet's load is the linear magnet's.
    m.coercivity = block.h_c;
    return m;
  }
  m.coercivity = block.h_c;
  const std::array<double, 2> mu =
      linear_femm_permeability(block.lam_type, fill, block.mu_x, block.mu_y, fail);
  m.mu_r = mu[0];
  if (mu[0] != mu[1]) {
    m.mu_r_axes = mu;
    m.source += " (anisotropic: mu_r " + format_number(mu[0]) + " along x (r), " +
                format_number(mu[1]) + " along y (z))";
  }
  return m;
}

}  // namespace rheomag::cases::femm
