// What Copy link adds for the exercise on screen: where a page of the site can find it.
#include <gtest/gtest.h>

#include <fstream>

#include "app/host/share_link.h"

using namespace shadelab;
namespace fs = std::filesystem;

namespace {

// A folder under the temporary directory, made afresh.
fs::path folder(const std::string& name) {
  const fs::path p = fs::temp_directory_path() / "shadelab_share_link" / name;
  fs::remove_all(p);
  fs::create_directories(p);
  return p;
}

}  // namespace

TEST(ShareLink, AnExerciseOfTheSiteIsNamedAndOneOfTheLinkCourseBringsItsZip) {
  const fs::path builtin = folder("exercises"), site = folder("site_course"), unpacked = folder("week3");
  const std::vector<fs::path> siteRoots{builtin, site};
  const LinkCourse course{"week3.zip", unpacked};

  ShareLink link{"lab=shading", ""};
  addExercise(link, "shading/blinn-phong", builtin, siteRoots, course);
  EXPECT_EQ(link.fragment, "lab=shading&exercise=shading%2Fblinn-phong");
  EXPECT_EQ(link.note, "");

  link = {"lab=surface", ""};
  addExercise(link, "surface/screen-tbn", site, siteRoots, course);
  EXPECT_EQ(link.fragment, "lab=surface&exercise=surface%2Fscreen-tbn") << "the site's own course needs no zip";

  link = {"lab=shading", ""};
  addExercise(link, "shading/toon", unpacked, siteRoots, course);
  EXPECT_EQ(link.fragment, "lab=shading&exercise=shading%2Ftoon&course=week3.zip");

  // The same folder written another way is the same folder.
  link = {"lab=shading", ""};
  addExercise(link, "shading/toon", unpacked / ".", siteRoots, course);
  EXPECT_EQ(link.fragment, "lab=shading&exercise=shading%2Ftoon&course=week3.zip");
}

TEST(ShareLink, AnExerciseNoPageCanReachIsLeftOutAndNamed) {
  const fs::path builtin = folder("exercises"), dropped = folder("week4");
  ShareLink link{"lab=shading", "the scene is a file of yours (my.obj): the link opens the lab's default scene"};
  addExercise(link, "shading/toon", dropped, {builtin}, {});
  EXPECT_EQ(link.fragment, "lab=shading");
  EXPECT_EQ(
      link.note,
      "the scene is a file of yours (my.obj): the link opens the lab's default scene; exercise shading/toon is "
      "from course week4, which a link cannot reach: put week4.zip on the site and add course=week4.zip (or build "
      "the site with ./web.sh --exercises week4)");

  // No exercise selected, or none found: the link is unchanged.
  link = {"lab=shading", ""};
  addExercise(link, "", builtin, {builtin}, {});
  addExercise(link, "shading/nowhere", fs::path(), {builtin}, {});
  EXPECT_EQ(link.fragment, "lab=shading");
  EXPECT_EQ(link.note, "");
}
