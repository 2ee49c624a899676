#include "render/gl/shader_program.h"

#include <stdexcept>
#include <vector>

#include "render/gl/gl.h"

namespace stanceplan::render {
namespace {

GLuint compile(const std::string& name, GLenum type, const char* source) {
  const GLuint shader = glCreateShader(type);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetShaderiv(shader, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetShaderInfoLog(shader, length, nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error("shader \"" + name + "\" (" +
                             (type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                             ") does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

ShaderProgram::ShaderProgram(const std::string& name, const char* vertex_source,
                             const char* fragment_source)
    : name_(name) {
  const GLuint vs = compile(name, GL_VERTEX_SHADER, vertex_source);
  const GLuint fs = compile(name, GL_FRAGMENT_SHADER, fragment_source);
  program_ = glCreateProgram();
  glAttachShader(program_, vs);
  glAttachShader(program_, fs);
  glLinkProgram(program_);
  glDeleteShader(vs);
  glDeleteShader(fs);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint length = 0;
    glGetProgramiv(program_, GL_INFO_LOG_LENGTH, &length);
    std::vector<char> log(static_cast<size_t>(length) + 1, '\0');
    glGetProgramInfoLog(program_, length, nullptr, log.data());
    glDeleteProgram(program_);
    throw std::runtime_error("shader \"" + name + "\" does not link: " + log.data());
  }
}

ShaderProgram::~ShaderProgram() {
  glDeleteProgram(program_);
}

void ShaderProgram::use() const {
  glUseProgram(program_);
}

int ShaderProgram::location(const char* name) {
  auto it = locations_.find(name);
  if (it == locations_.end())
    it = locations_.emplace(name, glGetUniformLocation(program_, name)).first;
  return it->second;
}

void ShaderProgram::set(const char* name, int v) {
  glUniform1i(location(name), v);
}
void ShaderProgram::set(const char* name, float v) {
  glUniform1f(location(name), v);
}
void ShaderProgram::set(const char* name, const Eigen::Vector2f& v) {
  glUniform2f(location(name), v.x(), v.y());
}
void ShaderProgram::set(const char* name, const Eigen::Vector3f& v) {
  glUniform3f(location(name), v.x(), v.y(), v.z());
}
void ShaderProgram::set(const char* name, const Color& c) {
  glUniform4f(location(name), c.r, c.g, c.b, c.a);
}
// Eigen matrices are column-major, as GL expects.
void ShaderProgram::set(const char* name, const Eigen::Matrix3f& m) {
  glUniformMatrix3fv(location(name), 1, GL_FALSE, m.data());
}
void ShaderProgram::set(const char* name, const Eigen::Matrix4f& m) {
  glUniformMatrix4fv(location(name), 1, GL_FALSE, m.data());
}

}  // namespace stanceplan::render
