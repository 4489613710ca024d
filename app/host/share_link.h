// A link to what is on screen: the part of the page's URL after '#', which the page reads back
// (app/web/main_web.cpp): "lab=shadows&scene=learnopengl&camera=...&shadows.filter=pcss". A
// teacher copies it and the class opens the same frame. Only settings that differ from the lab's
// defaults are written, so the link stays short and says what was changed.
#pragma once
#include <filesystem>
#include <string>
#include <vector>

namespace shadelab {

class LabHost;

struct ShareLink {
  std::string fragment;  // without the '#'
  std::string note;      // what the link cannot carry (a mesh file of the user's own), or ""
};

ShareLink shareLink(LabHost& host);

// The course zip of the site a page was opened with ("course=week3.zip"), and the folder
// web/course.js unpacked it into; empty on the desktop and in a page opened without one.
struct LinkCourse {
  std::string zip;
  std::filesystem::path folder;
};

// The exercise on screen, added to a link: "exercise=ID", with "course=ZIP" when it comes from
// the course zip the page was opened with. `root` is the folder it was found in (exerciseRootOf);
// `siteRoots` the folders every page of the site lists (the built-in exercises, and the course the
// site was built with). An exercise from anywhere else (a course folder on this disk, a zip
// dropped on the page) is one the link cannot reach: it is left out, and the note says so.
void addExercise(ShareLink& link, const std::string& id, const std::filesystem::path& root,
                 const std::vector<std::filesystem::path>& siteRoots, const LinkCourse& course);

// A link's fragment read back: percent-decoding each "key=value" ('+' is a space), as the page
// does when it opens.
struct OpenedLink {
  std::string lab, scene, camera;
  std::vector<std::string> sets;  // "lab.key=value"
  bool measure = false;
  std::string exercise;               // "shading/blinn-phong": the Exercises section opens on it
  std::string course;                 // "week3.zip": a course zip of the page's site (web/course.js unpacks it)
  bool check = false;                 // press its Check once the page has drawn
  bool builtin = false;               // the student's folder is not searched (after a shader lost the context)
  bool present = false;               // presentation mode: the viewport fills the page (F11 / Esc leave it)
  int frames = 0;                     // draw this many frames, print their timing and stop (tools/web_bench.sh)
  bool cycle = false;                 // switch to every lab in turn (tools/web_bench.sh: the tab's memory)
  std::vector<std::string> problems;  // keys it does not know, with the valid ones
};
OpenedLink openLink(const std::string& fragment);

// RFC 3986 percent-encoding of everything but the unreserved characters.
std::string percentEncode(const std::string& text);

}  // namespace shadelab
