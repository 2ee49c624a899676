#include "planner/model/package_path.h"

#include <cstdlib>
#include <filesystem>

namespace stanceplan {
namespace fs = std::filesystem;

std::vector<std::string> PackagePath::search_directories() const {
  std::vector<std::string> result = directories;
  if (!use_ros_package_path) return result;
  const char* env = std::getenv("ROS_PACKAGE_PATH");
  if (env == nullptr) return result;
  std::string entries(env);
  size_t start = 0;
  while (start <= entries.size()) {
    const size_t end = std::min(entries.find(':', start), entries.size());
    if (end > start) result.push_back(entries.substr(start, end - start));
    start = end + 1;
  }
  return result;
}

namespace {

bool exists_file(const fs::path& path) {
  std::error_code ec;
  return fs::is_regular_file(path, ec);
}

std::optional<std::string> try_candidate(const fs::path& path, std::vector<std::string>* tried) {
  if (tried) tried->push_back(path.string());
  if (exists_file(path)) return path.lexically_normal().string();
  return std::nullopt;
}

}  // namespace

std::optional<std::string> resolve_uri(const std::string& uri, const std::string& base_dir,
                                       const PackagePath& packages,
                                       std::vector<std::string>* tried) {
  const std::string package_prefix = "package://";
  const std::string file_prefix = "file://";
  if (uri.rfind(package_prefix, 0) == 0) {
    const std::string rest_with_name = uri.substr(package_prefix.size());
    const size_t slash = rest_with_name.find('/');
    const std::string rest = slash == std::string::npos ? "" : rest_with_name.substr(slash + 1);
    for (const std::string& dir : packages.search_directories()) {
      if (auto hit = try_candidate(fs::path(dir) / rest_with_name, tried)) return hit;
      if (auto hit = try_candidate(fs::path(dir) / rest, tried)) return hit;
    }
    return std::nullopt;
  }
  std::string path = uri.rfind(file_prefix, 0) == 0 ? uri.substr(file_prefix.size()) : uri;
  fs::path candidate(path);
  if (candidate.is_relative()) candidate = fs::path(base_dir) / candidate;
  return try_candidate(candidate, tried);
}

}  // namespace stanceplan
