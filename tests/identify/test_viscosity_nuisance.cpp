// The per-recording viscosity factor of a family fit (identify/viscosity_nuisance.hpp, issue 32
// point 5): which parameters it scales, and its recovery on real recordings given a known,
// concealed temperature history.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

#include "identify/current_dependent_fit.hpp"
#include "identify/viscosity_nuisance.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::identify;
using rheomag::lumped::Recording;

namespace {

/// The UTFSM tests (M. Quiroz 2022) at 0, 0.25, ..., 1 A of 10 mm / 1 Hz, then of 25 mm /
/// 0.5 Hz: two recordings at each current; empty if absent.
std::vector<Recording> utfsm_two_strokes() {
  const std::string dir = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
  std::vector<Recording> recs;
  for (const char* test : {"10mm1Hz", "25mm0x5Hz"})
    for (const char* current : {"0A", "0x25A", "0x5A", "0x75A", "1A"}) {
      const std::string path = dir + test + current + ".csv";
      if (!std::filesystem::exists(path)) return {};
      recs.push_back(rheomag::lumped::read_recording(path));
    }
  return recs;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t h = v.size() / 2;
  return v.size() % 2 ? v[h] : 0.5 * (v[h - 1] + v[h]);
}

std::vector<double> fits(const FamilyFit& f) {
  std::vector<double> out;
  for (const auto& m : f.training) out.push_back(m.metrics.fit_percent);
  return out;
}

}  // namespace

// The damper model's consistency (Herschel-Bulkley), its per-field part and its pre-yield
// viscosity scale with the fluid's viscosity; its yield, stiffness and friction do not.
TEST(ViscosityNuisance, ScalesTheViscousTermsOnly) {
  using rheomag::lumped::PhenoKind;
  std::vector<std::string> scaled;
  const auto& params = rheomag::lumped::pheno_params(PhenoKind::damper);
  for (std::size_t k = 0; k < params.size(); ++k)
    if (scales_with_viscosity(PhenoKind::damper, k)) scaled.push_back(params[k].name);
  EXPECT_EQ(scaled, (std::vector<std::string>{"consistency", "consistency_per_field",
                                              "pre_yield_viscous"}));
  // Every model has at least one viscous term.
  for (const auto& name : greybox_model_names()) {
    PhenoKind kind;
    ASSERT_TRUE(rheomag::lumped::parse_pheno_kind(name, kind));
    bool any = false;
    for (std::size_t k = 0; k < rheomag::lumped::pheno_params(kind).size(); ++k)
      any = any || scales_with_viscosity(kind, k);
    EXPECT_TRUE(any) << name;
  }
  // The factor stands for a temperature at 2 %/K: 0.8 is 11.2 K warmer (-ln 0.8 / 0.02).
  EXPECT_NEAR(viscosity_temperature_offset(0.8), 11.157, 1e-3);
}

// Real recordings with a concealed temperature history: each of ten UTFSM tests (10 mm / 1 Hz
// and 25 mm / 0.5 Hz at five currents) is given its own viscosity factor (a fluid at another
// temperature, 0.7 to 1.3: -13 to +18 K at 2 %/K) differentially — the family model's output at
// that factor minus at 1, added to the measured force — and the family is fitted with the
// nuisance (0.5:2, two rounds). What the recordings identify: a factor that varies smoothly with
// the current is the same model as other per-field viscous terms (consistency_per_field), so
// only the factors' ratio between the two recordings at one current is scored. Reference: the
// concealed ratio, corrected by the ratio the nuisance finds on the unmodified recordings (their
// own scatter). Tolerance: each current's ratio within 15 % (measured 0.2-10.6 %: the shared
// parameters take up part of each factor; the project's bar for parameters on real data is
// 30 %), on the side of 1 the concealed ratio is on; the median FIT on the heated
// recordings with the nuisance at least 1 point above the fit without it.
TEST(ViscosityNuisance, RecoversAConcealedTemperatureHistoryOnRealRecordings) {
  const std::vector<Recording> original = utfsm_two_strokes();
  if (original.empty()) GTEST_SKIP() << "shared data absent";
  FamilyFitOptions plain;
  plain.greybox.starts = 2;
  const FamilyFit base = fit_current_dependent(original, "damper", {}, plain);
  const std::vector<double> concealed = {1.0, 0.8, 1.15, 0.7, 1.25, 0.85, 1.1, 0.75, 1.3, 0.9};
  std::vector<Recording> heated = original;
  for (std::size_t r = 0; r < heated.size(); ++r) {
    const auto cold = simulate_greybox(original[r], base.fit);
    const auto hot = simulate_greybox(original[r], with_viscosity_factor(base.fit, concealed[r]));
    auto& y = heated[r].columns[heated[r].meta.output];
    for (std::size_t k = 0; k < y.size(); ++k) y[k] += hot[k] - cold[k];
  }
  FamilyFitOptions with = plain;
  with.viscosity_nuisance = ViscosityNuisance{0.5, 2.0, 2};
  const FamilyFit own = fit_current_dependent(original, "damper", {}, with);
  const FamilyFit found = fit_current_dependent(heated, "damper", {}, with);
  const FamilyFit without = fit_current_dependent(heated, "damper", {}, plain);
  const auto factor = [](const FamilyFit& f, std::size_t r) {
    EXPECT_TRUE(f.training[r].viscosity_factor.has_value());
    return f.training[r].viscosity_factor.value_or(0.0);
  };
  for (std::size_t r = 0; r < heated.size(); ++r)
    std::cout << original[r].csv_path << ": factor on the unmodified " << factor(own, r)
              << ", on the heated " << factor(found, r) << " (concealed " << concealed[r]
              << "); FIT " << without.training[r].metrics.fit_percent << " -> "
              << found.training[r].metrics.fit_percent << "\n";
  const std::size_t half = heated.size() / 2;
  for (std::size_t r = 0; r < half; ++r) {
    const double ratio = factor(found, r) / factor(found, r + half);
    const double expected =
        concealed[r] / concealed[r + half] * factor(own, r) / factor(own, r + half);
    std::cout << "current " << r * 0.25 << " A: ratio " << ratio << ", expected " << expected
              << "\n";
    EXPECT_NEAR(ratio / expected, 1.0, 0.15) << r * 0.25 << " A";
    EXPECT_GT(std::log(ratio) * std::log(expected), 0.0) << r * 0.25 << " A";
  }
  EXPECT_GT(median(fits(found)), median(fits(without)) + 1.0);
}
