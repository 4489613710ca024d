// The workarounds for llvmpipe's held textures and scenes (driver_caveats.h: HeldTextures,
// HeldScenes): the driver keeps a deleted texture alive while it is the last one cleared through a
// framebuffer, the last whose mipmaps were made, or the last sampled on a unit in a stage, and keeps
// a drawn scene's commands and the textures it read until it hands that scene out again. On each
// lab switch DriverStandIns moves all of these references onto small textures of its own, which
// live as long as the host (made once: made and deleted per switch, they were themselves held).
// The host makes one only where llvmpipe runs.
#pragma once
#include <vector>

#include "app/gl/handle.h"

namespace gl {

class DriverStandIns {
 public:
  DriverStandIns();  // a context must be current; restores the bindings it changes
  // Moves the driver's references onto the stand-ins; the host calls it when a lab has been destroyed.
  // Leaves framebuffer 0 and no texture bound on the active unit; the tests, culling and colour
  // mask as they were.
  void takeDriverReferences();

 private:
  // One pixel, into the framebuffer bound, drawn by programs that sample the 1x1 `texel_` on each
  // of sixteen units in the fragment stage and in a tessellation evaluation stage: the driver's
  // references to the last draw's textures are per unit and per stage, and only a draw that
  // samples that unit in that stage moves them on. Restores the active unit and patch size but
  // leaves no texture bound; the caller turns the tests and culling off and restores the program
  // and vertex array.
  void drawSamplingEveryUnit();
  // One long scene (a loop per pixel of the 512^2 stand-in) and 48 cleared 1x1 scenes behind it:
  // each finds every scene before it still queued and takes the next idle one, so the first 49
  // scenes the driver has are handed out once and let go of what they held. Checked, not assumed:
  // the long scene's fence must still be unsignalled after each of the 48, or the round is
  // repeated with four times the work. (HeldScenes; the driver keeps the scenes this makes.)
  void handOutEveryScene();

  struct SamplingProgram {
    ProgramName program;
    bool patches = false;  // drawn as one patch: it has tessellation stages
  };
  TextureName plain_, array_, texel_;
  FramebufferName framebuffer_;
  VertexArray vao_;
  std::vector<SamplingProgram> programs_;  // linked once, with the stand-ins (none on OpenGL ES)
  ProgramName longScene_;                  // handOutEveryScene's loop per pixel (llvmpipe only)
  TextureName sceneTarget_;                // and the 1x1 target its cleared scenes clear
  FramebufferName sceneFramebuffer_;
};

}  // namespace gl
