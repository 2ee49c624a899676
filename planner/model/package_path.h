#pragma once
// Resolution of `package://NAME/REST` URIs (ROS convention, ../shared/robots/README.md): for each
// directory DIR of the search path (explicit directories first, then ROS_PACKAGE_PATH), the URI
// is DIR/NAME/REST if that exists, else DIR/REST if that exists; the first hit wins.
#include <optional>
#include <string>
#include <vector>

namespace stanceplan {

struct PackagePath {
  std::vector<std::string> directories;  // explicit --package-path directories, in order
  bool use_ros_package_path = true;      // append the ROS_PACKAGE_PATH entries

  // Every directory that will be searched, in order.
  std::vector<std::string> search_directories() const;
};

// Resolves a mesh reference from a URDF: `package://...`, `file://...`, an absolute path, or a
// path relative to the URDF's folder (base_dir). nullopt when nothing exists; *tried (optional)
// receives the candidate paths that were tried.
std::optional<std::string> resolve_uri(const std::string& uri, const std::string& base_dir,
                                       const PackagePath& packages,
                                       std::vector<std::string>* tried = nullptr);

}  // namespace stanceplan
