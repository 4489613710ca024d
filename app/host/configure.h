// Configuring a host from text, in one fixed order (lab, scene, settings, actions, camera): the
// command line, a rubric's configuration and the page's link all go through here, so they agree
// on a frame.
#pragma once
#include <string>
#include <vector>

#include "app/host/lab_host.h"

namespace shadelab {

// Applies a camera ("yaw=30,pitch=20,..."): parsed over the framed camera; near/far refit unless given.
std::string applyCamera(LabHost& host, const std::string& spec);
// Lab, scene ("" = keep), "lab.key=value" settings, actions, camera, in that order. "" or the
// first thing that could not be applied.
std::string configureHost(LabHost& host, const std::string& lab, const std::string& scene,
                          const std::vector<std::string>& sets, const std::vector<std::string>& actions,
                          const std::string& camera);

}  // namespace shadelab
