// The id ledger: ids carried by overlap, rooms that come back taking their ids back, the frame
// moving, and the ledger saved and read back (a restart); hand-made label images with hand-computed
// answers.
#include "topocut/segmentation/id_ledger.h"

#include <sys/resource.h>

#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "segmentation/incremental/label_rows.h"

#include "topocut/core/error.h"

namespace topocut {
namespace {

using testing::labels_of;

// next with each label l renamed ids[l].
cv::Mat named(const cv::Mat& next, const std::vector<int>& ids) {
  cv::Mat out = next.clone();
  for (int r = 0; r < out.rows; ++r)
    for (int c = 0; c < out.cols; ++c) out.at<int>(r, c) = ids[static_cast<std::size_t>(next.at<int>(r, c))];
  return out;
}

TEST(IdLedger, ARoomThatFlickersKeepsItsIdsAndUsesNoNewOnes) {
  // One room, then cut in two (the cut-off part gets id 2), then whole again, then cut again: the
  // part takes id 2 back instead of a third id, however often the cut comes and goes.
  IdLedger ledger(cv::Size(8, 1));
  const cv::Mat whole = labels_of({"11111111"});
  const cv::Mat cut = labels_of({"11111222"});
  cv::Mat published = named(whole, ledger.carry(cv::Mat(), whole, 1));
  EXPECT_EQ(cv::countNonZero(published != whole), 0);
  for (int round = 0; round < 3; ++round) {
    SCOPED_TRACE(round);
    published = named(cut, ledger.carry(published, cut, 2));
    EXPECT_EQ(cv::countNonZero(published != cut), 0);  // the larger part keeps 1, the other is 2
    published = named(whole, ledger.carry(published, whole, 1));
    EXPECT_EQ(cv::countNonZero(published != whole), 0);
  }
  EXPECT_EQ(ledger.next_id(), 3);  // ids used: 2 for a room that flickered six times
}

TEST(IdLedger, ARoomThatComesBackAfterAMergeTakesItsIdBack) {
  // Rooms 4 and 7 merge (7's id retires where it lay), then part again: 7 comes back where it was.
  IdLedger ledger(9, cv::Mat::zeros(1, 8, CV_32SC1));
  const cv::Mat apart = labels_of({"44447777"});
  const cv::Mat merged = labels_of({"11111111"});
  std::vector<int> ids = ledger.carry(apart, merged, 1);
  EXPECT_EQ(ids, (std::vector<int>{0, 4}));  // a tie: the lower old id
  EXPECT_EQ(ledger.retired().at<int>(0, 6), 7);
  const cv::Mat again = labels_of({"22222111"});  // labels in another order than before
  ids = ledger.carry(named(merged, {0, 4}), again, 2);
  EXPECT_EQ(ids, (std::vector<int>{0, 7, 4}));  // 4 goes to the larger overlap; label 1 lies where 7 was
  EXPECT_EQ(ledger.next_id(), 9);
}

TEST(IdLedger, ARoomFoundAgainWithNewlySeenSpaceTakesItsIdBack) {
  // A cut-off part (id 2, two cells) merges back into room 1, then the robot sees more and the cut is
  // found again: the part now holds its two old cells and more new ones than that, so most of it does
  // not lie where 2 was, but it covers all of where 2 was: it takes 2 back. Again one round later
  // with a still larger part: ids used stay 2 for one room that came and went three times.
  IdLedger ledger(cv::Size(8, 3));
  const cv::Mat cut = labels_of({"11111122", "00000000", "00000000"});
  const cv::Mat whole = labels_of({"11111111", "00000000", "00000000"});
  const cv::Mat grown = labels_of({"11111122", "00002222", "00000000"});
  const cv::Mat merged_grown = labels_of({"11111111", "11111111", "00000000"});
  const cv::Mat grown_more = labels_of({"11111122", "00002222", "00222222"});
  cv::Mat published = named(cut, ledger.carry(cv::Mat(), cut, 2));
  published = named(whole, ledger.carry(published, whole, 1));
  EXPECT_EQ(ledger.retired_cells(2), 2);
  EXPECT_EQ(ledger.carry(published, grown, 2), (std::vector<int>{0, 1, 2}));  // 2 of its 6 cells where 2 was
  published = named(grown, {0, 1, 2});
  published = named(merged_grown, ledger.carry(published, merged_grown, 1));
  EXPECT_EQ(ledger.retired_cells(2), 6);  // where it lay last
  EXPECT_EQ(ledger.carry(published, grown_more, 2), (std::vector<int>{0, 1, 2}));  // 6 of its 12
  EXPECT_EQ(ledger.next_id(), 3);
}

TEST(IdLedger, ARoomCoveringLessThanHalfOfWhereOneLayTakesANewId) {
  // Retired room 5 lay on 4 cells; a new room holding 2 of them among 6 of its own neither lies
  // mostly where 5 was nor covers most of it: a new id, not 5.
  IdLedger ledger(6, labels_of({"5555", "0000"}));
  const cv::Mat previous = labels_of({"0000", "0000"});
  const cv::Mat next = labels_of({"1100", "1111"});
  EXPECT_EQ(ledger.carry(previous, next, 1), (std::vector<int>{0, 6}));
  EXPECT_EQ(ledger.next_id(), 7);
}

TEST(IdLedger, NamingAWindowWeighsWhereARoomLayInTheWholeMap) {
  // Retired 5 lay on 4 cells, 2 of them in the window (columns 4-7); retired 6 on 2 cells, both in it.
  // Label 1 covers 5's 2 cells of the window among 6 of its own: all of 5 the window sees, but only
  // half of where 5 lay in the map: a new id. Label 2 covers all of where 6 lay among 6 cells of its
  // own: 6 back.
  IdLedger ledger(7, labels_of({"00555500", "00000066", "00000000"}));
  const cv::Mat in_window = labels_of({"1111", "1122", "2222"});
  std::vector<int> ids{0, 0, 0};
  const int fresh = ledger.name(cv::Rect(4, 0, 4, 3), in_window, cv::Mat(), ids, [](int) { return true; });
  EXPECT_EQ(ids, (std::vector<int>{0, 7, 6}));
  EXPECT_EQ(fresh, 1);
  EXPECT_EQ(ledger.next_id(), 8);
}

TEST(IdLedger, CountsWhereEachRetiredRoomLayAsCellsAreOverwrittenAndFallOutside) {
  IdLedger ledger(9, labels_of({"5566", "0000"}));
  EXPECT_EQ(ledger.retired_cells(5), 2);
  EXPECT_EQ(ledger.retired_cells(6), 2);
  ledger.retire(0, 1, 3, 7);  // room 7 disappears over one cell of 5 and one of 6
  EXPECT_EQ(ledger.retired_cells(5), 1);
  EXPECT_EQ(ledger.retired_cells(6), 1);
  EXPECT_EQ(ledger.retired_cells(7), 2);
  ledger.move(cv::Point(-1, 0), cv::Size(4, 2));  // the map's first column falls outside
  EXPECT_EQ(ledger.retired_cells(5), 0);
  EXPECT_EQ(ledger.retired_cells(7), 2);
  EXPECT_EQ(ledger.retired_cells(6), 1);
  EXPECT_EQ(ledger.retired_cells(8), 0);  // never disappeared
}

TEST(IdLedger, NamingAWindowRevivesOnlyAvailableIdsAndCountsTheNewOnes) {
  // A window of the map (columns 2-5): label 1 lies where retired 5 was, label 2 where retired 6
  // was but 6 is not available (alive elsewhere), label 3 already has its id.
  IdLedger ledger(9, labels_of({"00556666", "00000000"}));
  const cv::Mat window_labels = labels_of({"1122", "3300"});
  std::vector<int> ids{0, 0, 0, -1};
  const int fresh = ledger.name(cv::Rect(2, 0, 4, 2), window_labels, cv::Mat(), ids, [](int id) { return id != 6; });
  EXPECT_EQ(ids, (std::vector<int>{0, 5, 9, -1}));
  EXPECT_EQ(fresh, 1);
  EXPECT_EQ(ledger.next_id(), 10);
}

TEST(IdLedger, MovingTheFrameMovesWhereRoomsLay) {
  IdLedger ledger(4, labels_of({"30", "00"}));
  ledger.move(cv::Point(1, 2), cv::Size(3, 4));  // the map grew: the old cell (0, 0) is now (2, 1)
  ASSERT_EQ(ledger.retired().size(), cv::Size(3, 4));
  EXPECT_EQ(ledger.retired().at<int>(2, 1), 3);
  EXPECT_EQ(cv::countNonZero(ledger.retired()), 1);
}

TEST(IdLedger, ASavedLedgerReadsBackAsItWas) {
  IdLedger ledger(12, labels_of({"00900", "00000", "88000"}));
  Segmentation published;
  published.labels = labels_of({"11033", "11033", "00330"});
  published.resolution = 0.05;
  published.origin = {-12.25, 3.0000000001};
  std::stringstream file;
  write_ledger(file, ledger, published);
  const SavedLedger saved = read_ledger(file);
  EXPECT_EQ(saved.ledger.next_id(), 12);
  EXPECT_EQ(cv::countNonZero(saved.ledger.retired() != ledger.retired()), 0);
  EXPECT_EQ(cv::countNonZero(saved.published.labels != published.labels), 0);
  EXPECT_EQ(saved.published.resolution, 0.05);
  EXPECT_EQ(saved.published.origin.x, -12.25);
  EXPECT_EQ(saved.published.origin.y, 3.0000000001);
}

TEST(IdLedger, ADamagedLedgerIsRefusedWithTheReason) {
  IdLedger ledger(5, labels_of({"0000", "0000"}));
  Segmentation published;
  published.labels = labels_of({"1122", "3344"});
  std::stringstream good;
  write_ledger(good, ledger, published);
  const std::string text = good.str();
  auto reason = [](const std::string& damaged) {
    std::istringstream in(damaged);
    try {
      read_ledger(in);
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(reason("P5\n4 2\n255\n").find("not an id ledger"), std::string::npos);
  EXPECT_NE(reason(text.substr(0, text.size() - 6)).find("damaged"), std::string::npos);  // cut short
  std::string bad_id = text;
  bad_id.replace(bad_id.find("labels\n1 2"), 10, "labels\n7 2");  // an id never handed out
  EXPECT_NE(reason(bad_id).find("labels are damaged"), std::string::npos);
  std::string bad_size = text;
  bad_size.replace(bad_size.find("size 4 2"), 8, "size 0 2");
  EXPECT_NE(reason(bad_size).find("size"), std::string::npos);
  std::string bad_version = text;
  bad_version.replace(bad_version.find(" 1\n"), 3, " 9\n");
  EXPECT_NE(reason(bad_version).find("version 9"), std::string::npos);
  EXPECT_EQ(reason(text), "accepted");
}

// A ledger file that declares the largest map it may (2^28 cells: 1 GiB of labels, 1 GiB of retired
// ids) and is then cut short is refused for what it is, before any image of that size is made: in a
// child process held to 256 MiB more address space than it has, the reason is "damaged", not an
// allocation failure. (AddressSanitizer reserves terabytes at start, so no such limit can hold there.)
TEST(IdLedger, AHugeDeclaredSizeWithADamagedBodyAllocatesNothing) {
#if defined(__SANITIZE_ADDRESS__)
  GTEST_SKIP() << "an address-space limit cannot hold under AddressSanitizer";
#else
  const std::string text = "topocut-id-ledger 1\nnext_id 3\nresolution 0.05\norigin 0 0\nsize 1048576 256\nlabels\n1 1048576\n2 5\n";
  auto limited_read = [&text] {
    rlimit limit{};
    getrlimit(RLIMIT_AS, &limit);
    long pages = 0, resident = 0;
    if (std::FILE* f = std::fopen("/proc/self/statm", "r")) {
      if (std::fscanf(f, "%ld %ld", &pages, &resident) != 2) pages = 0;
      std::fclose(f);
    }
    limit.rlim_cur = static_cast<rlim_t>(pages) * 4096 + (256L << 20);
    setrlimit(RLIMIT_AS, &limit);
    std::istringstream in(text);
    try {
      read_ledger(in);
    } catch (const Error& e) {
      std::exit(std::string(e.what()).find("damaged (row 1)") != std::string::npos ? 0 : 3);
    } catch (...) {
      std::exit(4);  // out of memory: the image was made before the file was read
    }
    std::exit(5);
  };
  EXPECT_EXIT(limited_read(), ::testing::ExitedWithCode(0), "");
#endif
}

}  // namespace
}  // namespace topocut
