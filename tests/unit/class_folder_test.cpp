// A class folder read as it comes: folders named by the students, Moodle's "Download all
// submissions" (in folders and loose) and Canvas's "Download Submissions", each student's files
// gathered with the platform's identity for them.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <fstream>

#include "app/cli/submissions.h"

namespace shadelab {
namespace {

namespace fs = std::filesystem;

struct ClassFolderTest : testing::Test {
  fs::path dir = fs::temp_directory_path() / ("shadelab-class-" + std::to_string(::getpid()));
  void SetUp() override {
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  void write(const std::string& relative, const std::string& text = "// shader\n") {
    fs::create_directories((dir / relative).parent_path());
    std::ofstream(dir / relative) << text;
  }
  // The names a submission's files are staged under, sorted.
  static std::vector<std::string> uploadNames(const Submission& s) {
    std::vector<std::string> names;
    for (auto& f : s.files) names.push_back(f.second);
    std::sort(names.begin(), names.end());
    return names;
  }
};

TEST_F(ClassFolderTest, FoldersNamedByTheStudentsAreOneSubmissionEach) {
  write("ana/shadows/pcf.glsl");
  write("bo.zip", "not read here");
  write("notes.txt");
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  EXPECT_EQ(folder.layout, ClassLayout::Named);
  ASSERT_EQ(folder.submissions.size(), 2u);
  EXPECT_EQ(folder.submissions[0].name, "ana");
  EXPECT_EQ(folder.submissions[1].name, "bo");
  EXPECT_TRUE(folder.submissions[1].zip);
  EXPECT_TRUE(folder.submissions[0].id.empty());
}

// Moodle 3.1 and later: a folder per student and plugin ("in folders", the default); an online
// text beside the files is the same student's. The participant id is the identity.
TEST_F(ClassFolderTest, MoodlesDownloadInFoldersIsOneSubmissionPerParticipant) {
  write("Ada Lovelace_123_assignsubmission_file_/pcf.glsl");
  write("Ada Lovelace_123_assignsubmission_file_/shaders/common/specular.glsl");
  write("Ada Lovelace_123_assignsubmission_onlinetext_/onlinetext.html");
  write("Team A-Grace Hopper_456_assignsubmission_file_/my.zip", "zip");
  write("grades.csv");  // a teacher's own file in the folder
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  EXPECT_EQ(folder.layout, ClassLayout::Moodle);
  ASSERT_EQ(folder.submissions.size(), 2u);
  const Submission& ada = folder.submissions[0];
  EXPECT_EQ(ada.name, "Ada Lovelace_123");
  EXPECT_EQ(ada.id, "123");
  EXPECT_EQ(ada.person, "Ada Lovelace");
  EXPECT_EQ(uploadNames(ada),
            (std::vector<std::string>{"onlinetext.html", "pcf.glsl", "shaders/common/specular.glsl"}));
  EXPECT_EQ(folder.submissions[1].person, "Team A-Grace Hopper");
  ASSERT_EQ(folder.ignored.size(), 1u);
  EXPECT_EQ(folder.ignored[0].rfind("grades.csv (not named as Moodle's", 0), 0u) << folder.ignored[0];

  const fs::path staged = dir.parent_path() / (dir.filename().string() + "-staged");
  fs::remove_all(staged);
  ASSERT_EQ(stageFiles(ada, staged), "");
  EXPECT_TRUE(fs::exists(staged / "shaders/common/specular.glsl"));
  EXPECT_TRUE(fs::exists(staged / "pcf.glsl"));
  fs::remove_all(staged);
}

// "Download submissions in folders" off: every file loose, the student's part of its name first.
TEST_F(ClassFolderTest, MoodlesDownloadOfLooseFilesIsGatheredPerParticipant) {
  write("Ada Lovelace_123_assignsubmission_file_pcf.glsl");
  write("Ada Lovelace_123_assignsubmission_file_specular.glsl");
  write("Participant_789_assignsubmission_file_pcf.glsl");  // blind marking: no name
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  EXPECT_EQ(folder.layout, ClassLayout::Moodle);
  ASSERT_EQ(folder.submissions.size(), 2u);
  EXPECT_EQ(uploadNames(folder.submissions[0]), (std::vector<std::string>{"pcf.glsl", "specular.glsl"}));
  EXPECT_EQ(folder.submissions[1].id, "789");
}

// Canvas: loose files "name[_late]_USERID_FILEID_file"; a file uploaded again is numbered
// ("pcf-1.glsl") and read under the name the student gave it.
TEST_F(ClassFolderTest, CanvassDownloadIsGatheredPerUserId) {
  write("lovelaceada_4567_8910_pcf-1.glsl");
  write("lovelaceada_4567_8911_notes_v2.txt");
  write("hoppergrace_late_5678_9001_shaders.zip", "zip");
  write("hoppergrace_late_5678_9002_pcf.glsl");
  write("hoppergrace_late_5678_9003_pcf-1.glsl");  // both names are hers: kept apart
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  EXPECT_EQ(folder.layout, ClassLayout::Canvas);
  ASSERT_EQ(folder.submissions.size(), 2u);
  const Submission& grace = folder.submissions[0];
  EXPECT_EQ(grace.name, "hoppergrace_5678");
  EXPECT_EQ(grace.id, "5678");
  EXPECT_EQ(uploadNames(grace), (std::vector<std::string>{"pcf-1.glsl", "pcf.glsl", "shaders.zip"}));
  const Submission& ada = folder.submissions[1];
  EXPECT_EQ(ada.id, "4567");
  EXPECT_EQ(uploadNames(ada), (std::vector<std::string>{"notes_v2.txt", "pcf.glsl"}));
  ASSERT_EQ(ada.notes.size(), 1u);
  EXPECT_NE(ada.notes[0].find("pcf-1.glsl read as pcf.glsl"), std::string::npos);
}

// Two uploads under one name: the newer (the larger file id, compared as a number) is taken.
TEST_F(ClassFolderTest, CanvasTakesTheNewerOfTwoUploadsWithOneName) {
  write("lovelaceada_4567_999_pcf.glsl", "older");
  write("lovelaceada_4567_1000_pcf.glsl", "newer");
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  ASSERT_EQ(folder.submissions.size(), 1u);
  const fs::path staged = dir.parent_path() / (dir.filename().string() + "-staged");
  fs::remove_all(staged);
  ASSERT_EQ(stageFiles(folder.submissions[0], staged), "");
  std::ifstream in(staged / "pcf.glsl");
  std::string text;
  std::getline(in, text);
  EXPECT_EQ(text, "newer");
  ASSERT_EQ(folder.submissions[0].notes.size(), 1u);
  EXPECT_NE(folder.submissions[0].notes[0].find("an older upload under the same name"), std::string::npos);
  fs::remove_all(staged);
}

// One file named as Canvas names them beside a class of zips does not make it Canvas's download.
TEST_F(ClassFolderTest, OneCanvasLikeNameAmongZipsIsNoDownload) {
  write("ana.zip", "zip");
  write("bo.zip", "zip");
  write("roster_2024_09_x.csv");
  ClassFolder folder;
  ASSERT_EQ(readClassFolder(dir, folder), "");
  EXPECT_EQ(folder.layout, ClassLayout::Named);
  EXPECT_EQ(folder.submissions.size(), 2u);
}

}  // namespace
}  // namespace shadelab
