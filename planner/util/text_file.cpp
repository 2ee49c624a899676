#include "planner/util/text_file.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include "planner/util/input_error.h"

namespace stanceplan {

std::string read_text_file(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) throw InputError(path + ": no such file");
  if (!fs::is_regular_file(status)) throw InputError(path + ": not a regular file (a folder?)");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot be read (no permission?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError(path + ": read error");
  return text.str();
}

}  // namespace stanceplan
