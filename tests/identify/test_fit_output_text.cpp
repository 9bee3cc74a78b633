// Issue 34, fit output: one rule flags a fitted parameter in `fit` and `fit-family` (text and
// report), the Bouc-Wen per-ampere pairs count as field-dependent, and fit-family states its
// sample rule. Reference: the rules themselves (exact strings).

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "identify/family_fit_output.hpp"
#include "identify/family_report.hpp"
#include "identify/greybox.hpp"
#include "lumped/phenomenological.hpp"

namespace {

using namespace rheomag;
using identify::FittedParameter;

FittedParameter parameter(double value, std::optional<double> se) {
  FittedParameter p;
  p.name = "k0";
  p.unit = "N/m";
  p.value = value;
  p.standard_error = se;
  return p;
}

// "k0 0.494 +- 7e+03" was printed by `fit` without a word; the relative error 1.4e4 > 1
// (kPoorlyIdentifiedRelativeError) flags it now.
TEST(FitOutputText, ParameterRemarkFlagsUnidentifiedParameters) {
  EXPECT_EQ(identify::parameter_remark(parameter(0.494, 7e3)),
            "poorly identified (s.e. 1.4e+04 x |value|)");
  EXPECT_EQ(identify::parameter_remark(parameter(0.494, 0.01)), "");
  EXPECT_EQ(identify::parameter_remark(parameter(0.494, std::nullopt)), "not identified");
  EXPECT_EQ(identify::parameter_remark(parameter(0.0, 2.0)), "poorly identified (s.e. 2, value 0)");
  FittedParameter held = parameter(1.0, std::nullopt);
  held.fixed = true;
  EXPECT_EQ(identify::parameter_remark(held), "held");
  FittedParameter bound = parameter(1.0, 0.1);
  bound.at_bound = true;
  EXPECT_EQ(identify::parameter_remark(bound), "at bound");
}

std::vector<FittedParameter> parameters_of(lumped::PhenoKind kind) {
  std::vector<FittedParameter> out;
  for (const auto& p : lumped::pheno_params(kind)) {
    FittedParameter f;
    f.name = p.name;
    f.unit = p.unit;
    out.push_back(f);
  }
  return out;
}

std::vector<std::string> dependent_names(lumped::PhenoKind kind) {
  std::vector<std::string> names;
  for (const auto& d : identify::field_dependent_parameters(parameters_of(kind)))
    names.push_back(d.name + (d.quadratic ? "+u^2" : ""));
  return names;
}

// The fit-family report said "(no field-dependent parameters)" for Bouc-Wen, whose alpha_b,
// c0_b and c1_b are per-ampere terms (alpha = alpha_a + alpha_b u, lumped/phenomenological.hpp).
TEST(FitOutputText, BoucWenPerAmpereTermsAreFieldDependent) {
  EXPECT_EQ(dependent_names(lumped::PhenoKind::bouc_wen),
            (std::vector<std::string>{"alpha", "c0", "c1"}));
  EXPECT_EQ(dependent_names(lumped::PhenoKind::bingham),
            (std::vector<std::string>{"yield", "viscous"}));
  EXPECT_EQ(dependent_names(lumped::PhenoKind::damper),
            (std::vector<std::string>{"yield+u^2", "consistency", "seal_friction"}));
}

// fit-family used every 4th sample without saying what that means.
TEST(FitOutputText, DecimationRuleIsStated) {
  EXPECT_EQ(identify::decimation_text(4),
            "samples: the fit uses every 4th sample of each training recording (--decimation 4, "
            "default 4: samples 0, 4, 8, ...; 1/4 of the cost); the FIT and RE below are computed "
            "on every sample");
  EXPECT_NE(identify::decimation_text(2).find("every 2nd sample"), std::string::npos);
  EXPECT_NE(identify::decimation_text(11).find("every 11th sample"), std::string::npos);
  EXPECT_NE(identify::decimation_text(1).find("every sample"), std::string::npos);
}

}  // namespace
