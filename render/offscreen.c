#define GL_GLEXT_PROTOTYPES /* libOSMesa exports the GL 3 framebuffer functions */
#include "offscreen.h"

#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>
#include <stdio.h>
#include <stdlib.h>

/* 4 is what llvmpipe offers (GL_MAX_SAMPLES) and plenty for 2D edges. */
#define WANTED_SAMPLES 4

struct tbr_offscreen {
  OSMesaContext context;
  uint8_t* pixels; /* the OSMesa colour buffer, RGBA, rows from the top */
  int width, height;
  GLuint framebuffer, renderbuffer; /* multisampled; 0 when drawing straight into pixels */
  int samples;
};

tbr_offscreen* tbr_offscreen_create(int width, int height, char* error, size_t error_size) {
  if (width < 1 || height < 1 || width > 8192 || height > 8192) {
    snprintf(error, error_size, "image size %dx%d is outside 1x1 to 8192x8192", width, height);
    return NULL;
  }
  tbr_offscreen* t = calloc(1, sizeof *t);
  if (t != NULL) t->pixels = malloc((size_t)width * (size_t)height * 4u);
  if (t == NULL || t->pixels == NULL) {
    if (t != NULL) free(t);
    snprintf(error, error_size, "no memory for a %dx%d image", width, height);
    return NULL;
  }
  t->width = width;
  t->height = height;
  /* a compatibility profile: gl_draw.c uses client-side vertex arrays */
  const int attributes[] = {OSMESA_FORMAT,
                            OSMESA_RGBA,
                            OSMESA_DEPTH_BITS,
                            0,
                            OSMESA_STENCIL_BITS,
                            0,
                            OSMESA_PROFILE,
                            OSMESA_COMPAT_PROFILE,
                            OSMESA_CONTEXT_MAJOR_VERSION,
                            3,
                            OSMESA_CONTEXT_MINOR_VERSION,
                            0,
                            0};
  t->context = OSMesaCreateContextAttribs(attributes, NULL);
  if (t->context == NULL || !OSMesaMakeCurrent(t->context, t->pixels, GL_UNSIGNED_BYTE, width, height)) {
    snprintf(error, error_size, "OSMesa could not create an OpenGL 3.0 compatibility context (%dx%d)", width, height);
    tbr_offscreen_destroy(t);
    return NULL;
  }
  OSMesaPixelStore(OSMESA_Y_UP, 0); /* row 0 of pixels is the top of the image, as PNG wants */

  GLint max_samples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &max_samples);
  t->samples = max_samples < WANTED_SAMPLES ? (int)max_samples : WANTED_SAMPLES;
  if (t->samples > 1) {
    glGenFramebuffers(1, &t->framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, t->framebuffer);
    glGenRenderbuffers(1, &t->renderbuffer);
    glBindRenderbuffer(GL_RENDERBUFFER, t->renderbuffer);
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, t->samples, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, t->renderbuffer);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE) {
      /* no multisampling here: draw straight into the OSMesa buffer, aliased */
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDeleteRenderbuffers(1, &t->renderbuffer);
      glDeleteFramebuffers(1, &t->framebuffer);
      t->framebuffer = t->renderbuffer = 0;
      t->samples = 1;
    }
  } else {
    t->samples = 1;
  }
  return t;
}

void tbr_offscreen_destroy(tbr_offscreen* t) {
  if (t == NULL) return;
  if (t->context != NULL) {
    OSMesaMakeCurrent(t->context, t->pixels, GL_UNSIGNED_BYTE, t->width, t->height);
    if (t->framebuffer != 0) {
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      glDeleteRenderbuffers(1, &t->renderbuffer);
      glDeleteFramebuffers(1, &t->framebuffer);
    }
    OSMesaDestroyContext(t->context);
  }
  free(t->pixels);
  free(t);
}

void tbr_offscreen_begin(tbr_offscreen* t) {
  OSMesaMakeCurrent(t->context, t->pixels, GL_UNSIGNED_BYTE, t->width, t->height);
  glBindFramebuffer(GL_FRAMEBUFFER, t->framebuffer);
  glViewport(0, 0, t->width, t->height);
}

const uint8_t* tbr_offscreen_finish(tbr_offscreen* t) {
  if (t->framebuffer != 0) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, t->framebuffer);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, t->width, t->height, 0, 0, t->width, t->height, GL_COLOR_BUFFER_BIT, GL_NEAREST);
  }
  /* with the OSMesa framebuffer bound: only then does glFinish copy it into pixels */
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glFinish();
  return t->pixels;
}

int tbr_offscreen_samples(const tbr_offscreen* t) { return t->samples; }
