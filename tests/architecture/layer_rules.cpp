#include "tests/architecture/layer_rules.hpp"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <functional>
#include <regex>
#include <sstream>
#include <stdexcept>

namespace rheomag::architecture {

namespace fs = std::filesystem;

namespace {

/// The cells of a Markdown table row "| a | b | c |", trimmed.
std::vector<std::string> cells_of(const std::string& row) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(row.substr(row.find('|') + 1));
  while (std::getline(in, cell, '|')) {
    const auto first = cell.find_first_not_of(" \t");
    const auto last = cell.find_last_not_of(" \t\r");
    cells.push_back(first == std::string::npos ? "" : cell.substr(first, last - first + 1));
  }
  if (!cells.empty() && cells.back().empty()) cells.pop_back();
  return cells;
}

/// The name in a first cell: the text between the first pair of backticks, else the cell.
std::string layer_name(const std::string& cell) {
  const auto open = cell.find('`');
  const auto close = open == std::string::npos ? open : cell.find('`', open + 1);
  return close == std::string::npos ? cell : cell.substr(open + 1, close - open - 1);
}

/// The words (letters, digits, '_') of `text`.
std::vector<std::string> words_of(const std::string& text) {
  std::vector<std::string> words;
  static const std::regex word("[A-Za-z0-9_]+");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), word); it != std::sregex_iterator();
       ++it)
    words.push_back(it->str());
  return words;
}

/// Throws naming a layer on a circle of the table.
void refuse_circles(const LayerTable& table, const std::string& where) {
  std::map<std::string, int> state;  // 0 unseen, 1 on the path, 2 done
  std::function<void(const std::string&, std::vector<std::string>&)> visit =
      [&](const std::string& layer, std::vector<std::string>& path) {
        if (state[layer] == 2) return;
        path.push_back(layer);
        if (state[layer] == 1) {
          std::string loop;
          for (const auto& p : path) loop += (loop.empty() ? "" : " -> ") + p;
          throw std::runtime_error(where + ": the layer table has a circle: " + loop);
        }
        state[layer] = 1;
        for (const auto& dep : table.at(layer)) visit(dep, path);
        state[layer] = 2;
        path.pop_back();
      };
  for (const auto& [layer, deps] : table) {
    std::vector<std::string> path;
    visit(layer, path);
  }
}

/// The source files under `dir` (recursively), sorted.
std::vector<fs::path> sources_under(const fs::path& dir) {
  std::vector<fs::path> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir)) {
    const auto ext = entry.path().extension();
    if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp" || ext == ".h"))
      files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace

LayerTable read_layer_table(const fs::path& doc) {
  std::ifstream in(doc);
  if (!in) throw std::runtime_error(doc.string() + ": cannot be read");
  std::vector<std::pair<int, std::vector<std::string>>> rows;
  std::string line;
  int number = 0;
  bool in_table = false;
  while (std::getline(in, line)) {
    ++number;
    const bool table_row = line.rfind("|", 0) == 0;
    if (!in_table) {
      const auto cells = table_row ? cells_of(line) : std::vector<std::string>{};
      in_table = cells.size() >= 2 && cells[0] == "layer" && cells[1] == "depends on";
      continue;
    }
    if (!table_row) break;
    if (line.find("---") != std::string::npos) continue;
    auto cells = cells_of(line);
    if (cells.size() < 2)
      throw std::runtime_error(doc.string() + ":" + std::to_string(number) +
                               ": a layer row needs at least two cells (layer, depends on)");
    rows.emplace_back(number, std::move(cells));
  }
  if (rows.empty())
    throw std::runtime_error(doc.string() +
                             ": no table with the header '| layer | depends on | ...'");
  LayerTable table;
  for (const auto& [row_line, cells] : rows) {
    const std::string name = layer_name(cells[0]);
    if (name.empty() || table.count(name))
      throw std::runtime_error(doc.string() + ":" + std::to_string(row_line) +
                               ": empty or repeated layer name '" + name + "'");
    table[name];
  }
  for (const auto& [row_line, cells] : rows) {
    auto& deps = table[layer_name(cells[0])];
    for (const auto& word : words_of(cells[1])) {
      if (word == "all") {
        for (const auto& [other, unused] : table)
          if (other != layer_name(cells[0])) deps.insert(other);
      } else if (table.count(word) && word != layer_name(cells[0])) {
        deps.insert(word);
      }
    }
  }
  refuse_circles(table, doc.string());
  return table;
}

std::set<std::string> allowed_layers(const LayerTable& table, const std::string& layer) {
  std::set<std::string> allowed{layer};
  std::vector<std::string> todo{layer};
  while (!todo.empty()) {
    const std::string next = todo.back();
    todo.pop_back();
    const auto it = table.find(next);
    if (it == table.end()) continue;
    for (const auto& dep : it->second)
      if (allowed.insert(dep).second) todo.push_back(dep);
  }
  return allowed;
}

std::vector<Violation> check_tree(const fs::path& root, const LayerTable& table,
                                  const std::set<std::string>& unlayered) {
  std::vector<Violation> out;
  static const std::regex include(R"(^\s*#\s*include\s*["<]([A-Za-z0-9_]+)/([^">]*)[">])");
  static const std::regex target(R"(\brheomag_([a-z0-9_]+)\b)");
  for (const auto& [layer, deps] : table) {
    const fs::path dir = root / layer;
    if (!fs::is_directory(dir)) continue;
    const auto allowed = allowed_layers(table, layer);
    for (const auto& file : sources_under(dir)) {
      std::ifstream in(file);
      std::string line;
      int number = 0;
      std::smatch m;
      while (std::getline(in, line)) {
        ++number;
        if (std::regex_search(line, m, include) && table.count(m[1]) && !allowed.count(m[1]))
          out.push_back({fs::relative(file, root).string(), number,
                         layer + " includes " + m[1].str() + "/" + m[2].str() + ", but " +
                             m[1].str() + " is not below " + layer + " in the layer table"});
      }
    }
    for (const auto& entry : fs::recursive_directory_iterator(dir)) {
      if (entry.path().filename() != "CMakeLists.txt") continue;
      std::ifstream in(entry.path());
      std::string line;
      int number = 0;
      while (std::getline(in, line)) {
        ++number;
        if (line.find('#') != std::string::npos) line.erase(line.find('#'));
        for (auto it = std::sregex_iterator(line.begin(), line.end(), target);
             it != std::sregex_iterator(); ++it) {
          const std::string used = (*it)[1];
          if (table.count(used) && !allowed.count(used))
            out.push_back({fs::relative(entry.path(), root).string(), number,
                           layer + " links rheomag_" + used + ", but " + used + " is not below " +
                               layer + " in the layer table"});
        }
      }
    }
  }
  for (const auto& entry : fs::directory_iterator(root)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_directory() && fs::exists(entry.path() / "CMakeLists.txt") && !table.count(name) &&
        !unlayered.count(name))
      out.push_back({name + "/CMakeLists.txt", 1,
                     "folder " + name + " builds code but has no row in the layer table"});
  }
  return out;
}

}  // namespace rheomag::architecture
