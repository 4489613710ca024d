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
// The stand-ins are made once and live as long as their owner (the host): whether a rasteriser
// thread holds them then changes nothing. Deleted after each use, as they first were, they were
// held by some threads and not others, and a lab entry's heap differed by their 3 MB from one
// entry to the next.
#pragma once
#include "gl/handle.h"

namespace gl {

class DriverStandIns {
 public:
  DriverStandIns();  // a context must be current; restores the bindings it changes
  // Moves the driver's references onto the stand-ins; the host calls it when a lab is torn down.
  // Leaves framebuffer 0 and no texture bound on the active unit.
  void takeDriverReferences();

 private:
  TextureName plain_, array_;
  FramebufferName framebuffer_;
};

}  // namespace gl
