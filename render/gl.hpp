#pragma once
// The one way render/ includes OpenGL: glad2's GL 3.3 core loader, generated at
// build time (render/CMakeLists.txt). It must come before anything that includes
// GL/gl.h. Whoever makes a context loads it: gladLoadGL(glfwGetProcAddress) in a
// window, OffscreenContext does it for a headless context (EGL or OSMesa).
#include <glad/gl.h>
