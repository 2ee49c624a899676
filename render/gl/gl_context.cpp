#include "render/gl/gl_context.h"

#include <GL/osmesa.h>

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "render/gl/gl.h"

namespace stanceplan::render {

// Rendering goes to framebuffer objects; OSMesa still wants a colour buffer to make the context
// current, so it gets a tiny one that is never drawn into.
constexpr int kDummySize = 4;

struct GlContext::Impl {
  OSMesaContext context = nullptr;
  std::vector<unsigned char> dummy = std::vector<unsigned char>(kDummySize * kDummySize * 4);
};

GlContext::GlContext() : impl_(std::make_unique<Impl>()) {
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            24,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_CORE_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            3,
                            0};
  impl_->context = OSMesaCreateContextAttribs(attributes, nullptr);
  if (impl_->context == nullptr)
    throw std::runtime_error("OSMesa: cannot create an OpenGL 3.3 core-profile context");
  make_current();
}

GlContext::~GlContext() {
  if (OSMesaGetCurrentContext() == impl_->context) OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
  OSMesaDestroyContext(impl_->context);
}

void GlContext::make_current() {
  if (OSMesaGetCurrentContext() == impl_->context) return;
  if (!OSMesaMakeCurrent(impl_->context, impl_->dummy.data(), GL_UNSIGNED_BYTE, kDummySize,
                         kDummySize))
    throw std::runtime_error("OSMesa: cannot make the context current");
}

std::string GlContext::renderer_name() const {
  const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return name != nullptr ? name : "";
}

void check_gl(const char* where) {
  const GLenum error = glGetError();
  if (error != GL_NO_ERROR) {
    char code[16];
    std::snprintf(code, sizeof(code), "0x%04x", error);
    throw std::runtime_error(std::string("OpenGL error ") + code + " in " + where);
  }
}

}  // namespace stanceplan::render
