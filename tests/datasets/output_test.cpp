// Output files: checked before any work, written all or nothing, unique temporary names.
#include <coverkit/datasets/path_io.h>
#include <coverkit/geometry/error.h>

#include "helpers/checkers.h"

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

using namespace coverkit;
namespace fs = std::filesystem;

namespace {
fs::path freshDir(const std::string& name) {
  const fs::path d = fs::path(COVERKIT_TEST_TMP) / "output" / name;
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}
std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}
void put(const fs::path& p, const std::string& s) { std::ofstream(p, std::ios::binary) << s; }
std::size_t temporaries(const fs::path& d) {
  std::size_t n = 0;
  for (const auto& e : fs::recursive_directory_iterator(d)) n += e.path().string().find("tmp-coverkit") != std::string::npos;
  return n;
}
std::string messageOf(const std::function<void()>& f) { return testing_helpers::inputErrorMessage(f); }
}  // namespace

TEST(OutputBatch, WritesEveryFileAndLeavesNoTemporary) {
  const fs::path d = freshDir("all");
  put(d / "old.json", "old");
  datasets::OutputBatch b;
  b.add((d / "old.json").string(), "new");
  b.add((d / "a.csv").string(), std::string("x\0y", 3));
  b.commit();
  EXPECT_EQ(slurp(d / "old.json"), "new");
  EXPECT_EQ(slurp(d / "a.csv"), std::string("x\0y", 3));
  EXPECT_EQ(temporaries(d), 0u);
}

TEST(OutputBatch, ARenameThatFailsLeavesNoFileAndRestoresReplacedOnes) {
  const fs::path d = freshDir("rollback");
  put(d / "first.json", "old first");
  fs::create_directories(d / "third.json" / "inside");  // a non-empty folder: renaming onto it fails
  datasets::OutputBatch b;
  b.add((d / "first.json").string(), "new first");
  b.add((d / "second.json").string(), "new second");
  b.add((d / "third.json").string(), "new third");
  const std::string msg = messageOf([&] { b.commit(); });
  EXPECT_NE(msg.find("third.json"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("Success"), std::string::npos) << msg;
  EXPECT_EQ(slurp(d / "first.json"), "old first");
  EXPECT_FALSE(fs::exists(d / "second.json"));
  EXPECT_TRUE(fs::is_directory(d / "third.json" / "inside"));
  EXPECT_EQ(temporaries(d), 0u);
}

TEST(OutputBatch, AFailureRemovesTheFoldersItCreated) {
  const fs::path d = freshDir("folders");
  fs::create_directories(d / "blocked.csv" / "inside");
  datasets::OutputBatch b((d / "new" / "deeper").string());
  b.addInFolder("results.csv", "r");
  b.add((d / "blocked.csv").string(), "b");
  EXPECT_THROW(b.commit(), InputError);
  EXPECT_FALSE(fs::exists(d / "new"));
  datasets::OutputBatch ok((d / "new" / "deeper").string());
  ok.addInFolder("results.csv", "r");
  ok.commit();
  EXPECT_EQ(slurp(d / "new" / "deeper" / "results.csv"), "r");
}

TEST(OutputBatch, TheMessageGivesTheRealReason) {
  const fs::path d = freshDir("reason");
  const std::string msg = messageOf([&] { datasets::writeFileAtomically((d / "missing" / "x.json").string(), "x"); });
  EXPECT_NE(msg.find("No such file or directory"), std::string::npos) << msg;
}

TEST(OutputBatch, ConcurrentWritersToOneFileDoNotShareATemporary) {
  const fs::path d = freshDir("concurrent");
  const std::string target = (d / "out.json").string();
  std::atomic<int> failures{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t)
    threads.emplace_back([&, t] {
      for (int k = 0; k < 50; ++k) {
        try {
          datasets::writeFileAtomically(target, std::string(1000 + t, static_cast<char>('a' + t)));
        } catch (const InputError&) {
          ++failures;
        }
      }
    });
  for (auto& th : threads) th.join();
  EXPECT_EQ(failures.load(), 0);
  const std::string content = slurp(target);
  ASSERT_GE(content.size(), 1000u);
  EXPECT_EQ(content, std::string(content.size(), content[0]));  // one writer's whole content
  EXPECT_EQ(temporaries(d), 0u);
}

TEST(OutputChecks, RefuseBeforeAnyWork) {
  const fs::path d = freshDir("checks");
  fs::create_directories(d / "folder.json");
  put(d / "file", "f");
  auto check = [](const fs::path& f, const std::vector<std::string>& ext) { return messageOf([&] { datasets::checkOutputFile(f.string(), "--out", ext); }); };
  EXPECT_NE(check(d / "missing" / "x.json", {".json"}).find("folder '" + (d / "missing").string() + "' does not exist"), std::string::npos);
  EXPECT_NE(check(d / "folder.json", {".json"}).find("is a folder"), std::string::npos);
  EXPECT_NE(check(d / "x.txt", {".json", ".csv"}).find("unknown output format '.txt' (expected .json or .csv)"), std::string::npos);
  EXPECT_NE(check(d / "file" / "x.json", {".json"}).find("is not a folder"), std::string::npos);
  EXPECT_EQ(check(d / "X.JSON", {".json"}), "");
  auto folder = [](const fs::path& f) { return messageOf([&] { datasets::checkOutputFolder(f.string(), "--out", {"results.csv"}); }); };
  EXPECT_NE(folder(d / "file").find("exists and is not a folder"), std::string::npos);
  EXPECT_NE(folder(d / "file" / "sub").find("--out"), std::string::npos);
  EXPECT_EQ(folder(d / "new" / "deeper"), "");
  EXPECT_FALSE(fs::exists(d / "new"));  // checking creates nothing
  fs::create_directories(d / "out" / "results.csv");
  EXPECT_NE(folder(d / "out").find("is a folder"), std::string::npos);
}
