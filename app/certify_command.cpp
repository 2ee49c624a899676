#include "app/certify_command.h"

#include "app/pipeline.h"

namespace stanceplan::app {

int run_certify(const std::string& path, std::ostream& out, std::ostream& err) {
  return certify_file(path, out, err);
}

}  // namespace stanceplan::app
