#include "client/viewer/headless_context.hpp"

#include <cstdio>
#include <cstring>

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <GLES2/gl2.h>

namespace ocean::viewer {

namespace {

std::string egl_error(const char* step) {
  char code[16];
  std::snprintf(code, sizeof code, "0x%04x", static_cast<unsigned>(eglGetError()));
  return std::string(step) + " failed (EGL error " + code + ")";
}

bool has_token(const char* list, const char* token) {
  if (!list) return false;
  const std::size_t n = std::strlen(token);
  for (const char* p = list; (p = std::strstr(p, token)) != nullptr; p += n)
    if ((p == list || p[-1] == ' ') && (p[n] == ' ' || p[n] == '\0')) return true;
  return false;
}

EGLDisplay open_display() {
  const char* client_ext = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (has_token(client_ext, "EGL_MESA_platform_surfaceless")) {
    auto get_platform_display =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (get_platform_display) {
      EGLDisplay d = get_platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
      if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
    }
  }
  EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
  if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) return d;
  return EGL_NO_DISPLAY;
}

}  // namespace

bool HeadlessContext::create(std::string& error) {
  destroy();
  EGLDisplay display = open_display();
  if (display == EGL_NO_DISPLAY) {
    error = egl_error("opening an EGL display (surfaceless Mesa platform, then the default display)") +
            "; are libegl1-mesa and libgl1-mesa-dri installed?";
    return false;
  }
  display_ = display;
  if (!eglBindAPI(EGL_OPENGL_ES_API)) {
    error = egl_error("eglBindAPI(EGL_OPENGL_ES_API)");
    destroy();
    return false;
  }
  const bool surfaceless = has_token(eglQueryString(display, EGL_EXTENSIONS), "EGL_KHR_surfaceless_context");
  const EGLint config_attribs[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_ES2_BIT,
                                   EGL_SURFACE_TYPE, surfaceless ? 0 : EGL_PBUFFER_BIT,
                                   EGL_NONE};
  EGLConfig config = nullptr;
  EGLint count = 0;
  if (!eglChooseConfig(display, config_attribs, &config, 1, &count) || count == 0) {
    error = egl_error("eglChooseConfig(OpenGL ES 2 renderable)");
    destroy();
    return false;
  }
  const EGLint context_attribs[] = {EGL_CONTEXT_CLIENT_VERSION, 2, EGL_NONE};
  context_ = eglCreateContext(display, config, EGL_NO_CONTEXT, context_attribs);
  if (context_ == EGL_NO_CONTEXT) {
    context_ = nullptr;
    error = egl_error("eglCreateContext(OpenGL ES 2)");
    destroy();
    return false;
  }
  if (!surfaceless) {
    const EGLint pbuffer_attribs[] = {EGL_WIDTH, 1, EGL_HEIGHT, 1, EGL_NONE};
    surface_ = eglCreatePbufferSurface(display, config, pbuffer_attribs);
    if (surface_ == EGL_NO_SURFACE) {
      surface_ = nullptr;
      error = egl_error("eglCreatePbufferSurface (display lacks EGL_KHR_surfaceless_context)");
      destroy();
      return false;
    }
  }
  EGLSurface s = surface_ ? static_cast<EGLSurface>(surface_) : EGL_NO_SURFACE;
  if (!eglMakeCurrent(display, s, s, static_cast<EGLContext>(context_))) {
    error = egl_error("eglMakeCurrent");
    destroy();
    return false;
  }
  const char* vendor = eglQueryString(display, EGL_VENDOR);
  const char* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  description_ = std::string("EGL ") + (vendor ? vendor : "?") + ", " + (renderer ? renderer : "?") + ", " +
                 (version ? version : "?") + (surfaceless ? ", surfaceless" : ", pbuffer");
  return true;
}

void HeadlessContext::destroy() {
  if (!display_) return;
  EGLDisplay display = static_cast<EGLDisplay>(display_);
  eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
  if (surface_) eglDestroySurface(display, static_cast<EGLSurface>(surface_));
  if (context_) eglDestroyContext(display, static_cast<EGLContext>(context_));
  eglTerminate(display);
  display_ = context_ = surface_ = nullptr;
}

}  // namespace ocean::viewer
