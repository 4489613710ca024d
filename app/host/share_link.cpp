#include "app/host/share_link.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "app/host/lab_host.h"
#include "app/lab/params.h"
#include "app/scene/scene_catalog.h"
#include "app/util/format.h"

namespace shadelab {

std::string percentEncode(const std::string& text) {
  std::string out;
  for (unsigned char c : text) {
    if (std::isalnum(c) || c == '-' || c == '_' || c == '.' || c == '~') {
      out += char(c);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", c);
      out += hex;
    }
  }
  return out;
}

namespace {

std::string percentDecode(const std::string& text) {
  std::string out;
  for (size_t i = 0; i < text.size(); ++i) {
    const auto hex = [](char c) { return std::isxdigit(static_cast<unsigned char>(c)) != 0; };
    if (text[i] == '%' && i + 2 < text.size() && hex(text[i + 1]) && hex(text[i + 2])) {
      out += char(std::stoi(text.substr(i + 1, 2), nullptr, 16));
      i += 2;
    } else {
      out += text[i] == '+' ? ' ' : text[i];
    }
  }
  return out;
}

}  // namespace

OpenedLink openLink(const std::string& fragment) {
  OpenedLink link;
  size_t start = fragment.empty() || fragment[0] != '#' ? 0 : 1;
  while (start < fragment.size()) {
    size_t end = fragment.find('&', start);
    if (end == std::string::npos) end = fragment.size();
    const std::string item = percentDecode(fragment.substr(start, end - start));
    start = end + 1;
    if (item.empty()) continue;
    const size_t eq = item.find('=');
    const std::string key = item.substr(0, eq), value = eq == std::string::npos ? "" : item.substr(eq + 1);
    if (key == "lab")
      link.lab = value;
    else if (key == "scene")
      link.scene = value;
    else if (key == "camera")
      link.camera = value;
    else if (key == "measure")
      link.measure = true;
    else if (key == "exercise")
      link.exercise = value;
    else if (key == "course")
      link.course = value;
    else if (key == "check")
      link.check = true;
    else if (key == "builtin")
      link.builtin = true;
    else if (key == "present")
      link.present = true;
    else if (key == "cycle")
      link.cycle = true;
    else if (key == "frames") {
      if (long n = 0; parseWholeNumber(value, 1, 1000000, n))
        link.frames = int(n);
      else
        link.problems.push_back("the link's frames='" + value + "' is not a number of frames (1 to 1000000)");
    } else if (key.find('.') != std::string::npos)
      link.sets.push_back(item);
    else
      link.problems.push_back("the link's key '" + key +
                              "' is unknown (valid: lab, scene, camera, measure, exercise, course, check, builtin, "
                              "present, frames, cycle, LAB.KEY)");
  }
  return link;
}

ShareLink shareLink(LabHost& host) {
  ShareLink link;
  const std::string lab(host.lab().id());
  link.fragment = "lab=" + percentEncode(lab);
  const auto scenes = listScenes(host.lab().scenes());
  const bool catalogued =
      std::any_of(scenes.begin(), scenes.end(), [&](const SceneEntry& s) { return s.id == host.sceneId(); });
  if (catalogued)
    link.fragment += "&scene=" + percentEncode(host.sceneId());
  else
    link.note = "the scene is a file of yours (" + host.sceneId() + "): the link opens the lab's default scene";
  link.fragment += "&camera=" + percentEncode(host.camera().toString());
  const Settings defaults = host.defaultSettings();  // the scene's own suggestions count as defaults
  for (const auto& setting : host.currentSettings()) {
    const auto d = std::find_if(defaults.begin(), defaults.end(), [&](auto& kv) { return kv.first == setting.first; });
    if (d != defaults.end() && d->second == setting.second) continue;
    // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on the one-expression form.
    link.fragment += '&';
    link.fragment += percentEncode(lab + "." + setting.first);
    link.fragment += '=';
    link.fragment += percentEncode(setting.second);
  }
  return link;
}

void addExercise(ShareLink& link, const std::string& id, const std::filesystem::path& root,
                 const std::vector<std::filesystem::path>& siteRoots, const LinkCourse& course) {
  if (id.empty() || root.empty()) return;
  const auto same = [&](const std::filesystem::path& a) {
    std::error_code ec;
    return !a.empty() && std::filesystem::equivalent(a, root, ec);
  };
  const bool fromLinkCourse = !course.zip.empty() && same(course.folder);
  if (!fromLinkCourse && std::none_of(siteRoots.begin(), siteRoots.end(), same)) {
    const std::string name =
        root.filename().empty() ? root.parent_path().filename().string() : root.filename().string();
    const std::string why = "exercise " + id + " is from course " + name + ", which a link cannot reach: put " + name +
                            ".zip on the site and add course=" + name + ".zip (or build the site with ./web.sh " +
                            "--exercises " + name + ")";
    link.note = link.note.empty() ? why : link.note + "; " + why;
    return;
  }
  link.fragment += "&exercise=" + percentEncode(id);
  if (fromLinkCourse) link.fragment += "&course=" + percentEncode(course.zip);
}

}  // namespace shadelab
