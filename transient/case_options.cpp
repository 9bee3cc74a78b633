#include "transient/case_options.hpp"

#include "case/femm_sidecar.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::transient {

TransientCaseOptions read_transient_case(const cases::Case& c) {
  TransientCaseOptions out;
  const cases::TomlSection top(c.table, "", cases::case_document_source(c));
  const auto section = top.table("transient");
  if (!section) return out;
  section->allow_only({"resistance", "region"});
  if (section->has("resistance")) out.resistance = section->positive("resistance");
  for (const cases::TomlSection& entry : section->table_array("region")) {
    entry.allow_only({"name", "model", "factor", "size"});
    RegionEddy remedy;
    remedy.region = entry.required_string("name");
    // Two remedies for one region: one of them was silently dropped.
    for (const RegionEddy& earlier : out.remedies)
      if (earlier.region == remedy.region)
        entry.fail("name", "region '" + remedy.region +
                               "' already has a remedy; expected one [[transient.region]] per "
                               "region");
    remedy.model = kEddyModelNames.parse(entry.required_string("model"), entry.where("model"));
    const bool sized = remedy.model == EddyModel::laminated || remedy.model == EddyModel::sintered;
    if (remedy.model == EddyModel::slotted) {
      if (!entry.has("factor")) entry.fail("factor", "a slotted region needs factor in [0, 1]");
      remedy.factor = entry.non_negative_or("factor", 0.0);
      if (remedy.factor > 1.0) entry.fail("factor", "expected a number in [0, 1]");
    } else if (entry.has("factor")) {
      entry.fail("factor", "only a slotted region takes factor");
    }
    if (sized) {
      remedy.size = entry.positive("size") * c.input.length_unit;
    } else if (entry.has("size")) {
      entry.fail("size", "only laminated and sintered regions take size");
    }
    out.remedies.push_back(remedy);
  }
  return out;
}

}  // namespace rheomag::transient
