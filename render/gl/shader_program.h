#pragma once
// A linked GLSL program with cached uniform locations. Needs its GL context current.
#include <Eigen/Core>
#include <string>
#include <unordered_map>

#include "render/image/color.h"

namespace stanceplan::render {

class ShaderProgram {
 public:
  // Compiles and links; throws std::runtime_error with the GLSL log and `name` on a fault.
  ShaderProgram(const std::string& name, const char* vertex_source, const char* fragment_source);
  ~ShaderProgram();
  ShaderProgram(const ShaderProgram&) = delete;
  ShaderProgram& operator=(const ShaderProgram&) = delete;

  void use() const;
  // Setters for the program in use; a name the program does not use is silently ignored (the GLSL
  // compiler removes unused uniforms).
  void set(const char* name, int v);
  void set(const char* name, float v);
  void set(const char* name, const Eigen::Vector2f& v);
  void set(const char* name, const Eigen::Vector3f& v);
  void set(const char* name, const Color& c);
  void set(const char* name, const Eigen::Matrix3f& m);
  void set(const char* name, const Eigen::Matrix4f& m);

 private:
  int location(const char* name);

  std::string name_;
  unsigned program_ = 0;
  std::unordered_map<std::string, int> locations_;
};

}  // namespace stanceplan::render
