#include "planner/io/request_file.h"

#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

#include "planner/solver/solver_wire.h"
#include "planner/util/atomic_file.h"
#include "planner/util/input_error.h"

namespace stanceplan {

void write_request_file(const std::string& path, const PostureRequest& request) {
  write_file_atomically(path, std::string(kRequestFileHeader) + serialize(request));
}

PostureRequest read_request_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": no such file");
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = kRequestFileHeader;
  if (bytes.compare(0, header.size(), header) != 0) {
    std::string found = bytes.substr(0, std::min<size_t>(bytes.find('\n'), 40));
    throw InputError(path + ": expected a solver request (first line \"" +
                     header.substr(0, header.size() - 1) +
                     "\", written by stanceplan plan --requests), found \"" + found + "\"");
  }
  try {
    return deserialize_request(bytes.substr(header.size()));
  } catch (const std::runtime_error& e) {
    throw InputError(path + ": a solver request cut short or written by another build (" +
                     e.what() + ")");
  }
}

}  // namespace stanceplan
