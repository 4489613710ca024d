// llvmpipe (Mesa 22.3) keeps textures alive after they and their framebuffers are deleted: the
// one last cleared through a framebuffer, and the layers of the one whose mipmaps were generated
// last, until another texture takes its place. A lab that leaves with a 1 GB shadow map cleared
// last, or 360 MB of mipmapped moment maps, would hold that memory while the next lab runs.
// DriverStandIns moves those references onto textures of its own: it clears a 512^2 texture
// through a framebuffer of its own and generates the mipmaps of a 512^2 array of eight layers
// (one byte a texel, about 3 MB). Smaller ones did not always reach every rasteriser thread: at
// 128^2 half the runs kept the old 360 MB. The driver also holds the textures the last draw
// sampled, unit by unit, so on a desktop context one pixel is drawn sampling a 1x1 stand-in on
// each of sixteen units (a point light's fill map on units 4 and 5 kept 256 MB).
// Its scenes hold what a burst of heavy work gave them (handOutEveryScene below).
// The stand-ins are made once and live as long as their owner (the host): whether a rasteriser
// thread holds them then changes nothing. Deleted after each use, as they first were, they were
// held by some threads and not others, and a lab entry's heap differed by their 3 MB from one
// entry to the next.
#pragma once
#include <vector>

#include "gl/handle.h"

namespace gl {

class DriverStandIns {
 public:
  DriverStandIns();  // a context must be current; restores the bindings it changes
  // Moves the driver's references onto the stand-ins; the host calls it when a lab is torn down.
  // Leaves framebuffer 0 and no texture bound on the active unit; the tests, culling and colour
  // mask as they were.
  void takeDriverReferences();

 private:
  // One pixel, into the framebuffer bound, drawn by programs that sample the 1x1 `texel_` on each
  // of sixteen units in the fragment stage and in a tessellation evaluation stage. The driver's
  // references to the last draw's textures are per unit and per stage, and only a draw that
  // samples a unit in that stage moves them on: a point light's lit program samples its fill
  // light's map on units 4 and 5, which nothing else reached, and the 8192^2 map (256 MB) stayed
  // held; a texture sampled in an evaluation stage (the surface lab's height map) stayed held
  // through every later program without one, or whose one sampled nothing (the window's soak:
  // steps of 1-2 MB on lab entries after the surface lab). A vertex stage's go with the next draw
  // on their own. Restores the active unit and patch size but leaves no texture bound; the caller
  // turns the tests and culling off and restores the program and vertex array.
  void drawSamplingEveryUnit();
  // llvmpipe bins draws into scenes that its rasteriser threads then draw. It makes a scene when
  // every one it has is still queued or being drawn, and keeps each for the life of the context;
  // a drawn scene keeps its binned commands (up to 36 MB) and a reference to every texture it read
  // until it is handed out again, and the driver hands out the first idle one. So a burst of heavy
  // work (the surface lab's millions of tessellated triangles) leaves scenes that the lighter
  // frames after it never reach: the window's soak found 38 and 115 MB held that way for the rest
  // of a run. This flushes one long scene (a loop per pixel of the 512^2 stand-in) and 48 cleared
  // 1x1 scenes behind it: each finds every scene before it still queued and takes the next idle
  // one, so the first 49 the driver has are handed out once and let go of what they held. Checked,
  // not assumed: the long scene's fence must still be unsignalled after each of the 48, or the
  // round is repeated with four times the work. The driver keeps the scenes this makes (about
  // 110 KB each, once). llvmpipe only.
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
