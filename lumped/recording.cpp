// Recording: column access with an error naming the file.

#include "lumped/recording.hpp"

#include "core/error.hpp"

namespace rheomag::lumped {

const std::vector<double>& Recording::column(const std::string& name) const {
  auto it = columns.find(name);
  if (it == columns.end())
    throw InputError(csv_path + ": no column '" + name + "' (the model needs it)");
  return it->second;
}

}  // namespace rheomag::lumped
