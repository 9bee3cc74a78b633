// Diagnosis parameters on real recordings (issue 33 point 3): the real-recording protocol.
// A `damper` family is fitted on UTFSM tests of another lab's damper (M. Quiroz, UTFSM 2022) that
// exclude the held-out 10 mm / 1 Hz test; the held-out test, unmodified and with a known moving
// mass, seal friction or spring added to its measured force, is diagnosed against that model
// (`--baseline`), and the found size is scored against the injected one.
// References and tolerances:
// - the unmodified recording: nothing named (a false finding fails);
// - the injection is sized at a tenth of the recording's force rms (m a_rms or F_c), added with
//   the model's sign; its acceleration comes from the displacement (second difference over
//   +-5 ms), not from the velocity column the diagnosis differentiates;
// - a stiffness (a gas spring, F += k (x - mean x)) sized the same way, at a tenth of the force
//   rms over the displacement's rms;
// - the effect is named and its size within 30 % of the injected (the target); a small
//   mass (20 kg) too, beyond what the unmodified recording carries;
// - differentially, the found size minus what the unmodified recording already carries of the
//   same candidate (its fit at the first step, accepted or not, now in the report) within 10 %:
//   the remaining error of the raw size is that held-out test's own mismatch with the model,
//   not a bias of the diagnosis (docs/validation.md, "Diagnosis parameters on real recordings");
// - the same with what the unmodified recording carries with the sign free (its signed size:
//   where it has less of an effect than the model, its positive fit is screened out and carries
//   0), named or, below the naming bar, as the injected recording's signed size, within 10 %:
//   measured -3.9 ... +1.9 % here (docs/validation.md, "Differenced with signed sizes").
// The same protocol on dyke1996's white-noise recording of another damper (Spencer et al. 1997, a
// random displacement and a random on/off command): one recording, so the model is fitted on its
// first 8 s (samples 0:24000) and the remaining 16.7 s are diagnosed. Its command moves, so a
// field lag can be injected too: the fitted model run on the command through a first-order lag
// of tau, minus the model on the command itself, added to the measured force; found within 30 %
// (measured 2 to 12 % high at 2, 5 and 20 ms).
// Needs shared/data beside the source tree (skipped otherwise).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

#include "diagnose/candidates/field_lag.hpp"
#include "diagnose/diagnose_change.hpp"
#include "diagnose/diagnose_run.hpp"
#include "identify/current_dependent_fit.hpp"
#include "identify/family_fit_output.hpp"
#include "identify/fit_model_json.hpp"
#include "lumped/recording_excerpt.hpp"
#include "lumped/recording_io.hpp"

namespace {

using rheomag::diagnose::Diagnosis;
using rheomag::diagnose::ModelBaseline;
using rheomag::lumped::Recording;

const std::string kDir = std::string(RHEOMAG_SHARED_DIR) + "/data/utfsm/";
constexpr double kPistonArea = 1e-3;  // [m^2] assumed (the sidecars give none)

/// The held-out test with the piston area the inertance needs (as a user's sidecar would add).
Recording held_out(const std::string& test) {
  auto rec = rheomag::lumped::read_recording(kDir + test + ".csv");
  rec.meta.rig.piston_area = kPistonArea;
  return rec;
}

/// A damper family fitted on the 10 mm / 1 Hz tests other than `test` and the 25 mm / 0.5 Hz
/// tests at 0.25 and 0.75 A, as the fitted-model JSON a user passes to --baseline; with the
/// 10 mm / 0 A test held out, the 25 mm / 0.5 Hz / 0 A test too, so that the family does not
/// extrapolate to a current below its tests'. Without it the field-dependent rod friction is
/// extrapolated to 0 A, and the unmodified 10 mm / 0 A test shows an 83 N friction the family
/// lacks (docs/validation.md).
ModelBaseline family_without(const std::string& test) {
  std::vector<std::string> names;
  for (const char* other : {"10mm1Hz0A", "10mm1Hz0x25A", "10mm1Hz0x5A", "10mm1Hz0x75A", "10mm1Hz1A",
                            "25mm0x5Hz0x25A", "25mm0x5Hz0x75A"})
    if (other != test) names.push_back(other);
  if (test == "10mm1Hz0A") names.push_back("25mm0x5Hz0A");
  std::vector<Recording> training;
  for (const auto& name : names)
    training.push_back(rheomag::lumped::read_recording(kDir + name + ".csv"));
  rheomag::identify::FamilyFitOptions options;
  options.greybox.starts = 2;  // the CLI's default
  const auto fit = rheomag::identify::fit_current_dependent(training, "damper", {}, options);
  const auto json =
      rheomag::identify::family_fit_json(fit, training.front().meta, options.decimation, false);
  return {rheomag::identify::parse_fit_model_json(json.dump(), "family.json"), "family.json"};
}

Diagnosis diagnose_with(const Recording& rec, const ModelBaseline& model) {
  rheomag::diagnose::DiagnoseOptions options;
  options.baseline_model = model;
  return rheomag::diagnose::diagnose(rec, options);
}

double rms_about_mean(const std::vector<double>& v) {
  double mean = 0.0, s = 0.0;
  for (double x : v) mean += x / static_cast<double>(v.size());
  for (double x : v) s += (x - mean) * (x - mean);
  return std::sqrt(s / static_cast<double>(v.size()));
}

/// Sign of the force's correlation with the velocity (the damper opposes the motion).
double model_sign(const Recording& rec) {
  const auto& f = rec.column("force");
  const auto& v = rec.column("velocity");
  double dot = 0.0;
  for (std::size_t k = 0; k < f.size(); ++k) dot += f[k] * v[k];
  return dot < 0.0 ? -1.0 : 1.0;
}

/// Acceleration from the displacement: second difference over +-h samples (h dt = 5 ms).
std::vector<double> acceleration(const Recording& rec) {
  const auto& x = rec.column("displacement");
  const double dt = rec.t[1] - rec.t[0];
  const std::size_t h = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(5e-3 / dt)));
  std::vector<double> a(x.size(), 0.0);
  for (std::size_t k = h; k + h < x.size(); ++k)
    a[k] = (x[k + h] - 2.0 * x[k] + x[k - h]) / (h * dt * h * dt);
  for (std::size_t k = 0; k < h; ++k) a[k] = a[h], a[x.size() - 1 - k] = a[x.size() - 1 - h];
  return a;
}

/// `name`'s first parameter among the findings of `d` (0 when not named).
double found(const Diagnosis& d, const std::string& name) {
  for (const auto& f : d.findings)
    if (f.effect->name() == name) return f.params.front();
  return 0.0;
}

/// What `d` fitted of `name` at its first step, accepted or not (0 when screened or not tried).
double carried(const Diagnosis& d, const std::string& name) {
  for (const auto& c : d.candidates)
    if (c.effect->name() == name && c.step == 0 && !c.params.empty()) return c.params.front();
  return found(d, name);
}

void print(const std::string& what, const Diagnosis& d) {
  std::cout << what << ": baseline FIT " << d.baseline_fit_percent << " %, final "
            << d.final_fit_percent << " %\n";
  for (const auto& f : d.findings)
    std::cout << "  named " << f.effect->name() << " " << f.params.front() << "\n";
  for (const auto& n : d.notes) std::cout << "  note: " << n << "\n";
}

/// What `d` carries of `name` against its baseline with the sign free, at its first step
/// (CandidateScore::signed_params); a failure when it has none.
double signed_size(const Diagnosis& d, const std::string& name) {
  for (const auto& c : d.candidates)
    if (c.effect->name() == name && c.step == 0 && !c.signed_params.empty())
      return c.signed_params.front();
  ADD_FAILURE() << name << " has no signed size";
  return 0.0;
}

/// The size of `name` in `d`: as named, else its signed first-step size (below the naming bar).
double named_or_signed(const Diagnosis& d, const std::string& name) {
  const double named = found(d, name);
  return named > 0.0 ? named : signed_size(d, name);
}

/// `rec` with a seal friction F_c tanh(v / 1 mm/s) added to its measured force (the model's sign).
Recording with_friction(const Recording& rec, double coulomb) {
  Recording rubbing = rec;
  const double sign = model_sign(rec);
  const auto& v = rec.column("velocity");
  for (std::size_t k = 0; k < v.size(); ++k)
    rubbing.columns["force"][k] += sign * coulomb * std::tanh(v[k] / 1e-3);
  return rubbing;
}

/// A spring of `share` of `original`'s force rms over its displacement rms, k (x - mean x),
/// added to its force, diagnosed against `model`: beyond the signed stiffness of the unmodified
/// recording's diagnosis `plain` (when given), within 10 %; at a tenth, also named as gas_spring
/// within 30 %.
void check_spring(const Recording& original, const Diagnosis* plain, const ModelBaseline& model,
                  const std::string& label, double share = 0.1) {
  const auto& x = original.column("displacement");
  const double x_mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  const double stiffness =
      share * rms_about_mean(original.column("force")) / rms_about_mean(x);  // [N/m]
  const double sign = model_sign(original);
  Recording sprung = original;
  for (std::size_t k = 0; k < x.size(); ++k)
    sprung.columns["force"][k] += sign * stiffness * (x[k] - x_mean);
  const Diagnosis d_spring = diagnose_with(sprung, model);
  print(label + " with " + std::to_string(stiffness) + " N/m", d_spring);
  const double k_found = found(d_spring, "gas_spring");
  std::cout << "stiffness: injected " << stiffness << " N/m, found " << k_found << " N/m\n";
  if (plain) {
    const double k_change =
        named_or_signed(d_spring, "gas_spring") - signed_size(*plain, "gas_spring");
    std::cout << "stiffness: signed change " << k_change << " N/m\n";
    EXPECT_NEAR(k_change / stiffness, 1.0, 0.1);
  }
  if (share < 0.1) return;
  EXPECT_GT(k_found, 0.0) << "the stiffness is not named";
  EXPECT_NEAR(k_found / stiffness, 1.0, 0.3);
}

/// The protocol on one held-out test: nothing named on it as recorded; a moving mass, a seal
/// friction (unless `friction_sized` is false) and a spring, each a tenth of its force rms, named
/// and sized.
void check_held_out(const std::string& test, bool friction_sized = true) {
  if (!std::filesystem::exists(kDir + test + ".csv")) GTEST_SKIP() << "shared data absent";
  const ModelBaseline model = family_without(test);
  const Recording original = held_out(test);
  const Diagnosis plain = diagnose_with(original, model);
  print(test + " as recorded", plain);
  EXPECT_TRUE(plain.findings.empty()) << "a false finding on the unmodified recording";

  const double sign = model_sign(original);
  const double force_rms = rms_about_mean(original.column("force"));
  const auto a = acceleration(original);
  const double mass = 0.1 * force_rms / rms_about_mean(a);  // [kg]
  Recording heavier = original;
  for (std::size_t k = 0; k < a.size(); ++k) heavier.columns["force"][k] += sign * mass * a[k];
  const Diagnosis d_mass = diagnose_with(heavier, model);
  print(test + " with " + std::to_string(mass) + " kg", d_mass);
  const double area2 = kPistonArea * kPistonArea;
  const double m_found = found(d_mass, "fluid_inertia") * area2;
  const double m_carried = carried(plain, "fluid_inertia") * area2;
  std::cout << "mass: injected " << mass << " kg, found " << m_found << " kg, carried before "
            << m_carried << " kg\n";
  EXPECT_GT(m_found, 0.0) << "the mass is not named";
  // The report gives the mass itself beside the inertance (A^2 L, the damper's force A^2 L a).
  for (const auto& f : d_mass.findings)
    if (f.effect->name() == "fluid_inertia") {
      ASSERT_EQ(f.derived.size(), 1u);
      EXPECT_EQ(f.derived[0].name, "moving_mass");
      EXPECT_EQ(f.derived[0].unit, "kg");
      EXPECT_NEAR(f.derived[0].value, m_found, 1e-9 * m_found);
    }
  EXPECT_NEAR(m_found / mass, 1.0, 0.3);
  EXPECT_NEAR((m_found - m_carried) / mass, 1.0, 0.1);
  const double m_signed = signed_size(plain, "fluid_inertia") * area2;  // carried, sign free
  EXPECT_NEAR((m_found - m_signed) / mass, 1.0, 0.1);
  // A small mass, 20 kg: the size a tenth of the force is at 3-5 Hz (issue 33). Sized within
  // 30 % beyond what the recording carries. While the family kept an inertance its training
  // tests do not show (9.6 kg without the 0.25 A test), every mass on that test was found 8 kg
  // low: 20 kg as 11.9 (docs/validation.md, "A mass the output delay takes"). At 1 Hz it is 1-2 %
  // of the force, so it need not be named: its size is the first step's fit, named or not. At
  // 0.5 A the delay runs to its bound with it; fitted with the delay held there, 20 kg came out
  // as 7.2 kg beyond the carried 3.1 ("The delay is not a channel skew here").
  constexpr double kSmallMass = 20.0;  // [kg]
  Recording lighter = original;
  for (std::size_t k = 0; k < a.size(); ++k)
    lighter.columns["force"][k] += sign * kSmallMass * a[k];
  const double m_small = carried(diagnose_with(lighter, model), "fluid_inertia") * area2;
  std::cout << "mass: injected " << kSmallMass << " kg, found " << m_small
            << " kg, carried with the sign free " << m_signed << " kg\n";
  EXPECT_NEAR((m_small - m_carried) / kSmallMass, 1.0, 0.3);
  EXPECT_NEAR((m_small - m_signed) / kSmallMass, 1.0, 0.1);

  const double coulomb = 0.1 * force_rms;  // [N]
  const Diagnosis d_friction = diagnose_with(with_friction(original, coulomb), model);
  print(test + " with " + std::to_string(coulomb) + " N of friction", d_friction);
  const double f_found = found(d_friction, "friction");
  const double f_carried = carried(plain, "friction");
  // Beyond what the unmodified recording carries with the sign free, named or not: sized at
  // 0 A too, where the calibrated output scale takes the named fit's share.
  const double f_change = named_or_signed(d_friction, "friction") - signed_size(plain, "friction");
  std::cout << "friction: injected " << coulomb << " N, found " << f_found << " N, carried before "
            << f_carried << " N, signed change " << f_change << " N\n";
  EXPECT_NEAR(f_change / coulomb, 1.0, 0.1);
  if (friction_sized) {
    EXPECT_GT(f_found, 0.0) << "the friction is not named";
    EXPECT_NEAR(f_found / coulomb, 1.0, 0.3);
  }

  check_spring(original, &plain, model, test);
}

// At 0 A the friction is not sized (open, issue 33): the recording's output scale, calibrated
// for its level, takes it. The 0 A force of this fluid (flow index 0.27) is nearly a square wave
// in the velocity, like a Coulomb force: 14.5 N of friction moves the calibrated scale from 0.961
// to 1.052 and leaves 2.3 N to the candidate, not named (docs/validation.md).
TEST(DiagnoseRealInjection, HeldOutTenMillimetreTestWithoutField) {
  check_held_out("10mm1Hz0A", false);
}

TEST(DiagnoseRealInjection, HeldOutTenMillimetreTestAtQuarterAmpere) {
  check_held_out("10mm1Hz0x25A");
}

TEST(DiagnoseRealInjection, HeldOutTenMillimetreTestAtHalfAmpere) {
  check_held_out("10mm1Hz0x5A");
}

// A 60 kg mass on the held-out 0.5 A test pushes the calibrated delay to its -2-sample bound
// (the unmodified test's is -1.35). Held there, the inertia candidate's fit is the worse one, so
// it is fitted with the delay free (docs/diagnosis.md, "A delay at its bound is tried free as
// well"), and the report says so. Reference: the injected mass, beyond what the unmodified
// recording carries, within 10 % (the protocol's differential tolerance), both as named (after
// the final joint re-fit, which frees the delay anyway) and as the candidate's first-step fit,
// which the selection compares; measured +0.7 % for both. The previous build's first-step fit,
// with the delay held at the bound: 50.3 kg (-21 %).
TEST(DiagnoseRealInjection, AMassThatPushedTheDelayToItsBoundIsFittedWithTheDelayFree) {
  const std::string test = "10mm1Hz0x5A";
  if (!std::filesystem::exists(kDir + test + ".csv")) GTEST_SKIP() << "shared data absent";
  const ModelBaseline model = family_without(test);
  const Recording original = held_out(test);
  const Diagnosis plain = diagnose_with(original, model);
  constexpr double kMass = 60.0;  // [kg]
  const auto a = acceleration(original);
  Recording heavier = original;
  for (std::size_t k = 0; k < a.size(); ++k)
    heavier.columns["force"][k] += model_sign(original) * kMass * a[k];
  const Diagnosis d = diagnose_with(heavier, model);
  print(test + " with 60 kg", d);
  EXPECT_NEAR(d.nuisance.delay_samples, -2.0, 1e-6) << "the delay is not at its bound";
  const double area2 = kPistonArea * kPistonArea;
  const double m_found = found(d, "fluid_inertia") * area2;
  const double m_carried = carried(plain, "fluid_inertia") * area2;
  std::cout << "mass: injected " << kMass << " kg, found " << m_found << " kg, carried "
            << m_carried << " kg\n";
  EXPECT_NEAR((m_found - m_carried) / kMass, 1.0, 0.1);
  const double m_first_step = carried(d, "fluid_inertia") * area2;
  EXPECT_NEAR((m_first_step - m_carried) / kMass, 1.0, 0.1);
  EXPECT_GT(std::abs(d.final_nuisance.delay_samples + 2.0), 0.1) << "the delay stayed at its bound";
  bool noted = false;
  for (const auto& n : d.notes)
    noted = noted || n.find("fluid_inertia was fitted with the output delay free") == 0;
  EXPECT_TRUE(noted) << "the report does not say the delay was freed";
}

TEST(DiagnoseRealInjection, HeldOutTenMillimetreTestAtThreeQuarterAmpere) {
  check_held_out("10mm1Hz0x75A");
}

// Effects below the naming bar, sized with their sign free (docs/diagnosis.md, "Signed sizes").
// On the held-out 1 A test, a seal friction and a spring of 3 % of the force rms: the friction is
// not named (the calibrated output scale takes most of a Coulomb force in phase with the yield
// force) and the spring is named 30 % low, because against this family the unmodified recording
// already has less of both (-22 N, -1 900 N/m with the sign free). Reference: the injected sizes,
// beyond the unmodified recording's signed sizes, within 10 % (the protocol's differential
// tolerance); measured -1.0 % and +4.4 % (the named sizes minus the carried ones: missed, -30 %).
TEST(DiagnoseRealInjection, EffectsBelowTheNamingBarAreSizedWithTheirSignFree) {
  const std::string test = "10mm1Hz1A";
  if (!std::filesystem::exists(kDir + test + ".csv")) GTEST_SKIP() << "shared data absent";
  const ModelBaseline model = family_without(test);
  const Recording original = held_out(test);
  const Diagnosis plain = diagnose_with(original, model);
  print(test + " as recorded", plain);
  const double coulomb = 0.03 * rms_about_mean(original.column("force"));  // [N]
  const Diagnosis d = diagnose_with(with_friction(original, coulomb), model);
  print(test + " with " + std::to_string(coulomb) + " N of friction", d);
  const double change = named_or_signed(d, "friction") - signed_size(plain, "friction");
  std::cout << "friction: injected " << coulomb << " N, signed change " << change << " N\n";
  EXPECT_NEAR(change / coulomb, 1.0, 0.1);
  check_spring(original, &plain, model, test, 0.03);
}

// The same differencing done by the diagnosis itself (`diagnose --reference`): the held-out
// 0.25 A test with a seal friction and a moving mass of a tenth of its force rms added, diagnosed
// against its family with the unmodified test as the reference (both fitted with one set of
// effects, today's output delay held at the reference's). Reference: the injected sizes, within
// 10 % (the protocol's differential tolerance, as above; measured -2.1 % for the friction and
// -0.2 % for the mass, docs/diagnosis.md "Against a reference recording"), also the mass taken
// together with the spring it cannot be told from on this drive; the spring, not injected,
// changes by less than a tenth of a spring of a tenth of the force (measured 0.5 % of it); and
// the reference's own diagnosis summarised (nothing named on it, as above).
TEST(DiagnoseRealInjection, TheChangeFromAReferenceRecordingIsTheEffect) {
  const std::string test = "10mm1Hz0x25A";
  if (!std::filesystem::exists(kDir + test + ".csv")) GTEST_SKIP() << "shared data absent";
  const ModelBaseline model = family_without(test);
  const Recording original = held_out(test);
  const double coulomb = 0.1 * rms_about_mean(original.column("force"));  // [N]
  const auto a = acceleration(original);
  const double mass = 0.1 * rms_about_mean(original.column("force")) / rms_about_mean(a);  // [kg]
  Recording changed = with_friction(original, coulomb);
  for (std::size_t k = 0; k < a.size(); ++k)
    changed.columns["force"][k] += model_sign(original) * mass * a[k];
  rheomag::diagnose::DiagnoseOptions options;
  options.baseline_model = model;
  options.reference = original;
  const Diagnosis d = rheomag::diagnose::diagnose(changed, options);
  print(test + " with friction and a mass, against the test as recorded", d);
  ASSERT_TRUE(d.reference.has_value());
  EXPECT_TRUE(d.reference->findings.empty()) << "a false finding on the reference";
  double f_change = 0.0, m_change = 0.0, k_change = 0.0;
  for (const auto& e : d.reference->changes) {
    std::cout << "  " << rheomag::diagnose::change_text(e) << "\n";
    if (e.effect->name() == "friction") f_change = e.change;
    if (e.effect->name() == "gas_spring") k_change = e.change;
    if (e.effect->name() == "fluid_inertia") {
      ASSERT_EQ(e.derived_change.size(), 1u);
      m_change = e.derived_change[0].value;  // the moving mass [kg]
      for (const auto& same : e.same_force)
        EXPECT_NEAR(same.combined_derived.at(0).value / mass, 1.0, 0.1) << same.effect->name();
    }
  }
  std::cout << "friction: injected " << coulomb << " N, change " << f_change
            << " N; mass: injected " << mass << " kg, change " << m_change << " kg; spring: change "
            << k_change << " N/m\n";
  EXPECT_NEAR(f_change / coulomb, 1.0, 0.1);
  EXPECT_NEAR(m_change / mass, 1.0, 0.1);
  const double spring = 0.1 * rms_about_mean(original.column("force")) /
                        rms_about_mean(original.column("displacement"));  // [N/m]
  EXPECT_LT(std::abs(k_change), 0.1 * spring) << "a spring changed that was not injected";
  EXPECT_EQ(d.reference->sized_on_one.size(), 0u);
}

// On one sinusoid a mass and a spring are one force (m a = -m w^2 x). The family of the 0.5 A
// test run on a 2 mm / 5 Hz sinusoid at 1 kHz (0.5 A, velocity the backward difference of the
// displacement, 0.3 % force noise) is the reference; the same with a mass of a tenth of the force
// rms is today's recording, both against that family. Reference: the injected mass within 10 %
// when taken together with the spring the drive cannot tell it from (measured +0.1 %; the mass
// alone lies anywhere along the two's valley, here -6.9 kg against 88.5 injected), and the two
// forces' shapes correlating at |r| >= 0.99 (measured -0.9999).
TEST(DiagnoseRealInjection, AMassOnASinusoidIsOneForceWithASpring) {
  const std::string test = "10mm1Hz0x5A";
  if (!std::filesystem::exists(kDir + test + ".csv")) GTEST_SKIP() << "shared data absent";
  const ModelBaseline model = family_without(test);
  Recording reference = held_out(test);
  constexpr double kRate = 1000.0, kStroke = 2e-3, kFrequency = 5.0;  // [Hz, m, Hz]
  const std::size_t n = 4000;
  reference.t.resize(n);
  std::vector<double> x(n), v(n), a(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    reference.t[k] = static_cast<double>(k) / kRate;
    x[k] = 0.5 * kStroke * std::sin(2.0 * M_PI * kFrequency * reference.t[k]);
    v[k] = k == 0 ? 0.0 : (x[k] - x[k - 1]) * kRate;
  }
  v[0] = v[1];
  for (std::size_t k = 1; k + 1 < n; ++k) a[k] = (x[k + 1] - 2.0 * x[k] + x[k - 1]) * kRate * kRate;
  a[0] = a[1], a[n - 1] = a[n - 2];
  reference.columns = {{"displacement", x},
                       {"velocity", v},
                       {"current", std::vector<double>(n, 0.5)},
                       {"force", std::vector<double>(n, 0.0)}};
  reference.columns["force"] = rheomag::identify::simulate_fit_model(reference, model.model);
  const double force_rms = rms_about_mean(reference.column("force"));
  std::mt19937 random(7);
  std::normal_distribution<double> noise(0.0, 0.003 * force_rms);
  for (double& f : reference.columns["force"]) f += noise(random);
  const double mass = 0.1 * force_rms / rms_about_mean(a);  // [kg]
  Recording heavier = reference;
  for (std::size_t k = 0; k < n; ++k)
    heavier.columns["force"][k] += model_sign(reference) * mass * a[k];
  rheomag::diagnose::DiagnoseOptions options;
  options.baseline_model = model;
  options.reference = reference;
  const Diagnosis d = rheomag::diagnose::diagnose(heavier, options);
  print("2 mm / 5 Hz with " + std::to_string(mass) + " kg, against it without", d);
  ASSERT_TRUE(d.reference.has_value());
  bool one_force = false;
  for (const auto& e : d.reference->changes) {
    std::cout << "  " << rheomag::diagnose::change_text(e) << "\n";
    if (e.effect->name() != "fluid_inertia") continue;
    for (const auto& same : e.same_force) {
      if (same.effect->name() != "gas_spring") continue;
      one_force = true;
      EXPECT_GE(std::abs(same.correlation), 0.99);
      EXPECT_NEAR(same.combined_derived.at(0).value / mass, 1.0, 0.1);
    }
  }
  EXPECT_TRUE(one_force) << "the mass is not reported as one force with the spring";
}

const std::string kDyke = std::string(RHEOMAG_SHARED_DIR) + "/data/dyke1996/ranran_50.csv";
constexpr std::size_t kDykeSplit = 24000;  // 8 s at 3 kHz: the model's samples

/// dyke1996's samples after kDykeSplit, and a `damper` model fitted on the samples before them
/// (as `rheomag fit ... --model damper --train 0:24000 --json`).
struct DykeSplit {
  Recording held_out;
  ModelBaseline model;
};

DykeSplit dyke_split() {
  const Recording rec = rheomag::lumped::read_recording(kDyke);
  rheomag::identify::GreyboxOptions options;
  options.train = rheomag::lumped::SampleRange{0, kDykeSplit};
  const auto fit = rheomag::identify::fit_greybox(rec, "damper", options);
  const auto json = rheomag::identify::fit_model_json(fit, rec.meta);
  return {rheomag::lumped::excerpt(rec, {kDykeSplit, rec.t.size()}),
          {rheomag::identify::parse_fit_model_json(json.dump(), "dyke.json"), "dyke.json"}};
}

/// The time constant of the field lag `d` named (mr_response_time or eddy_currents, which the
/// data cannot tell apart); 0 when neither is named.
double found_lag(const Diagnosis& d) {
  const double slow_fluid = found(d, "mr_response_time");
  return slow_fluid > 0.0 ? slow_fluid : found(d, "eddy_currents");
}

TEST(DiagnoseRealInjection, WhiteNoiseRecordingWithAFieldLag) {
  if (!std::filesystem::exists(kDyke)) GTEST_SKIP() << "shared data absent";
  const DykeSplit split = dyke_split();
  const Recording& original = split.held_out;
  const Diagnosis plain = diagnose_with(original, split.model);
  print("dyke1996 held-out part as recorded", plain);
  EXPECT_TRUE(plain.findings.empty()) << "a false finding on the unmodified recording";

  const auto base = rheomag::identify::simulate_fit_model(original, split.model.model);
  for (const double tau : {2e-3, 5e-3, 20e-3}) {
    Recording slow_field = original;
    slow_field.columns["command"] =
        rheomag::diagnose::candidates::first_order_lag(original.t, original.column("command"), tau);
    const auto slow = rheomag::identify::simulate_fit_model(slow_field, split.model.model);
    Recording lagging = original;
    for (std::size_t k = 0; k < slow.size(); ++k) lagging.columns["force"][k] += slow[k] - base[k];
    const Diagnosis d = diagnose_with(lagging, split.model);
    print("dyke1996 with a " + std::to_string(1e3 * tau) + " ms lag", d);
    const double tau_found = found_lag(d);
    std::cout << "lag: injected " << tau << " s, found " << tau_found << " s\n";
    EXPECT_GT(tau_found, 0.0) << "the lag is not named";
    EXPECT_NEAR(tau_found / tau, 1.0, 0.3);
  }
}

TEST(DiagnoseRealInjection, WhiteNoiseRecordingWithFrictionOrASpring) {
  if (!std::filesystem::exists(kDyke)) GTEST_SKIP() << "shared data absent";
  const DykeSplit split = dyke_split();
  const Recording& original = split.held_out;
  const double coulomb = 0.1 * rms_about_mean(original.column("force"));  // [N]
  const Diagnosis d_friction = diagnose_with(with_friction(original, coulomb), split.model);
  print("dyke1996 with " + std::to_string(coulomb) + " N of friction", d_friction);
  const double f_found = found(d_friction, "friction");
  std::cout << "friction: injected " << coulomb << " N, found " << f_found << " N\n";
  EXPECT_NEAR(f_found / coulomb, 1.0, 0.3);

  check_spring(original, nullptr, split.model, "dyke1996");
}

}  // namespace
