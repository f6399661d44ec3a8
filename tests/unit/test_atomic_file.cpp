// Atomic outputs (atomic_file.h): staged files and folders appear at their final paths together
// on commit, or not at all; a zip archive written by libzip into a staged file likewise.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <zip.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "error_of.h"
#include "slicereuse/util/atomic_file.h"
#include "slicereuse/util/error.h"
#include "temp_folder.h"

using namespace slicereuse;
namespace fs = std::filesystem;

namespace {

class AtomicOutputs : public test::TempFolderTest {
 protected:
  // Every entry of dir (and below), sorted: what a reader of the folder would see.
  std::vector<std::string> listing() const {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(fs::relative(e.path(), dir).string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

void spit(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_F(AtomicOutputs, FilesAndFolderAppearTogetherOnCommit) {
  StagedOutputs outputs;
  const std::string a = outputs.file(path("a.ctr")), b = outputs.file(path("b.enc"));
  const std::string f = outputs.folder(path("masks/"));  // a trailing slash names the same folder
  EXPECT_EQ(fs::path(f).parent_path(), fs::path(dir));
  spit(a, "A");
  spit(b, "B");
  spit(f + "/layer00000.png", "P");
  EXPECT_FALSE(fs::exists(path("a.ctr")) || fs::exists(path("b.enc")) || fs::exists(path("masks")));
  outputs.commit();
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.ctr", "b.enc", "masks", "masks/layer00000.png"}));
  EXPECT_EQ(slurp(path("a.ctr")) + slurp(path("b.enc")) + slurp(path("masks/layer00000.png")), "ABP");
}

TEST_F(AtomicOutputs, NothingAppearsWithoutCommitAndOldOutputsStay) {
  spit(path("a.ctr"), "old");
  {
    StagedOutputs outputs;
    spit(outputs.file(path("a.ctr")), "new");
    spit(outputs.file(path("b.enc")), "new");
    spit(outputs.folder(path("masks")) + "/layer00000.png", "P");
    // A failure here (error, cancel) destroys outputs without commit.
  }
  EXPECT_EQ(listing(), std::vector<std::string>{"a.ctr"});
  EXPECT_EQ(slurp(path("a.ctr")), "old");
}

TEST_F(AtomicOutputs, FolderIntoAFolderWithEntriesMovesItsEntries) {
  fs::create_directory(path("masks"));
  spit(path("masks/layer00000.png"), "old");
  spit(path("masks/notes.txt"), "mine");
  StagedOutputs outputs;
  const std::string f = outputs.folder(path("masks"));
  spit(f + "/layer00000.png", "new0");
  spit(f + "/layer00001.png", "new1");
  outputs.commit();
  EXPECT_EQ(listing(), (std::vector<std::string>{"masks", "masks/layer00000.png", "masks/layer00001.png",
                                                 "masks/notes.txt"}));
  EXPECT_EQ(slurp(path("masks/layer00000.png")), "new0");
  EXPECT_EQ(slurp(path("masks/notes.txt")), "mine");
}

// A target that is a folder would fail only at the rename in commit(), after the outputs staged
// before it had replaced theirs: file() refuses it up front.
TEST_F(AtomicOutputs, AFileOntoAFolderIsRefusedBeforeAnythingIsWritten) {
  spit(path("a.ctr"), "old");
  fs::create_directory(path("a.enc"));
  {
    StagedOutputs outputs;
    spit(outputs.file(path("a.ctr")), "new");
    try {
      outputs.file(path("a.enc"));
      ADD_FAILURE() << "staged a file onto a folder";
    } catch (const Error& e) {
      EXPECT_EQ(std::string(e.what()), "cannot write '" + path("a.enc") + "': it is a folder");
    }
  }
  EXPECT_EQ(listing(), (std::vector<std::string>{"a.ctr", "a.enc"}));
  EXPECT_EQ(slurp(path("a.ctr")), "old");
}

TEST_F(AtomicOutputs, StagedFileKeepsTheModeOfTheFileItReplaces) {
  spit(path("a.ctr"), "old");
  ::chmod(path("a.ctr").c_str(), 0640);
  StagedOutputs outputs;
  spit(outputs.file(path("a.ctr")), "new");
  outputs.commit();
  struct stat st;
  ASSERT_EQ(::stat(path("a.ctr").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 07777, 0640u);
  EXPECT_EQ(slurp(path("a.ctr")), "new");
}

TEST_F(AtomicOutputs, ZipArchiveWrittenByLibzipIntoAStagedFile) {
  spit(path("job.sl1"), "old");
  StagedOutputs outputs;
  const std::string staged = outputs.file(path("job.sl1"));
  int error = 0;
  zip_t* z = zip_open(staged.c_str(), ZIP_TRUNCATE, &error);
  ASSERT_NE(z, nullptr) << error;
  const char text[] = "hello";
  ASSERT_GE(zip_file_add(z, "a.txt", zip_source_buffer(z, text, 5, 0), 0), 0);
  ASSERT_EQ(zip_close(z), 0);
  EXPECT_EQ(slurp(path("job.sl1")), "old");  // until commit
  outputs.commit();
  z = zip_open(path("job.sl1").c_str(), ZIP_RDONLY | ZIP_CHECKCONS, &error);
  ASSERT_NE(z, nullptr) << error;
  EXPECT_EQ(zip_get_num_entries(z, 0), 1);
  zip_discard(z);
  EXPECT_EQ(listing(), std::vector<std::string>{"job.sl1"});
}

TEST_F(AtomicOutputs, WriteAtRewritesWhatWasWrittenAndGoesOnAtTheEnd) {
  AtomicFile file(path("h.bin"));
  file.write("0000body", 8);
  file.write_at(1, "HE", 2);
  file.write("tail", 4);
  EXPECT_ERROR(file.write_at(10, "xyz", 3), "bytes 10..13 are not within the 12 bytes written");
  file.commit();
  EXPECT_EQ(slurp(path("h.bin")), "0HE0bodytail");
}

TEST_F(AtomicOutputs, ErrorsNameThePath) {
  spit(path("plain"), "x");
  StagedOutputs outputs;
  try {
    outputs.folder(path("plain"));
    ADD_FAILURE() << "a file is not a folder";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path("plain") + "': it exists and is not a folder"), std::string::npos);
  }
  try {
    outputs.file(path("no/such/folder/a.ctr"));
    ADD_FAILURE() << "missing folder";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(path("no/such/folder/a.ctr")), std::string::npos);
  }
  EXPECT_NO_THROW(check_writable(path("masks/")));
}
