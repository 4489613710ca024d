#include "app/host/configure.h"

namespace shadelab {

std::string applyCamera(LabHost& host, const std::string& spec) {
  if (spec.empty()) return {};
  if (auto err = host.camera().parse(spec); !err.empty()) return err;
  if (spec.find("near=") == std::string::npos && spec.find("far=") == std::string::npos) {
    const Bounds b = host.scene().bounds;
    host.camera().fitDepthRange(b.center(), b.radius());
  }
  return {};
}

std::string configureHost(LabHost& host, const std::string& lab, const std::string& scene,
                          const std::vector<std::string>& sets, const std::vector<std::string>& actions,
                          const std::string& camera) {
  if (!lab.empty() && lab != host.lab().id())
    if (auto e = host.selectLab(lab); !e.empty()) return e;
  if (!scene.empty())
    if (auto e = host.selectScene(scene); !e.empty()) return e;
  for (auto& s : sets)
    if (auto e = host.set(s); !e.empty()) return "--set: " + e;
  for (auto& a : actions)
    if (auto e = host.runAction(a); !e.empty()) return "--do: " + e;
  return applyCamera(host, camera);
}

}  // namespace shadelab
