// How an image truth is made for the current settings: described once (the settings it is drawn
// with, the camera, the size), then drawn one jittered frame at a time (accumulated references)
// or traced (the lab's g-buffer now, its CPU part in a job). The Measurer runs these steps as
// jobs; renderTruthNow runs them at once.
#pragma once
#include <string>

#include "app/host/lab_host.h"

namespace shadelab {

struct TruthRequest {
  ReferenceSpec spec;
  Settings viewSettings;   // the settings measured (the truth's frames restore whatever is current)
  Settings truthSettings;  // with the truth's overrides applied
  OrbitCamera camera;      // captured: the student may orbit while a truth is being made
  glm::ivec2 size{0};
  float time = 0.0f;
  // Names the image: lab, scene load, truth settings, camera, size, time, jitter grid. Two
  // configurations that differ only in what the truth ignores (a bias, a PCF size) share it.
  std::string key;
};

// `view`: settings applied over the truth's overrides (one of the lab's measured views).
TruthRequest describeTruth(LabHost& host, glm::ivec2 size, float time, const Settings& view = {});
// One frame of the truth shifted by `jitter` pixels, drawn into `target` (of req.size) and read back.
ImageF drawTruthFrame(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target, glm::vec2 jitter);
// Part `slice` of that frame (of req.spec.slices), not read back: the window's measurer draws one
// part per GL step; after the last, target holds the frame drawTruthFrame would have read.
void drawTruthSlice(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target, glm::vec2 jitter,
                    int slice);
// Traced truths: the GL part now, under the truth's settings; returns the CPU part.
TraceWork beginTrace(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target);
// Truths traced on the GPU: the g-buffer now, under the truth's settings; returns the GL steps.
GlTraceStep beginGlTrace(LabHost& host, const TruthRequest& req, const gl::RenderTarget& target);
// Everything at once (tests, LabHost::renderReference).
ImageF renderTruthNow(LabHost& host, const TruthRequest& req);

}  // namespace shadelab
