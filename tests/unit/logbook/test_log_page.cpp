// Reading the logbook in pages (logbook/log_page.h, issue 56 item 4): the pages joined are list()
// whole, in (time_on, id) order, each at most `limit`; a QSO that shares its time with another is
// neither skipped nor repeated at a page's edge; the ADIF pages joined are write_adif's export.
#include <doctest/doctest.h>
#include <unistd.h>

#include <filesystem>

#include "logbook/adif.h"
#include "logbook/log_page.h"
#include "support/qso_samples.h"

using namespace tb::logbook;
namespace fs = std::filesystem;

namespace {
struct PageBook {
  fs::path dir = fs::temp_directory_path() / ("trakbox-logpage-" + std::to_string(::getpid()));
  std::unique_ptr<Logbook> book;
  PageBook() {
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::string err;
    book = Logbook::open((dir / "logbook.sqlite").string(), err);
    REQUIRE_MESSAGE(book, err);
    // 7 QSOs, three at the same second (the cursor's id breaks the tie), one deleted.
    const std::int64_t times[] = {300, 100, 200, 200, 200, 400, 500};
    const char* calls[] = {"K1AA", "K1AB", "K1AC", "K1AD", "K1AE", "K1AF", "K1AG"};
    for (int i = 0; i < 7; ++i) {
      Qso q = tb::testing::rs44_qso();
      q.id = 0;
      q.call = calls[i];
      q.time_on = 1796160000 + times[i];
      REQUIRE(book->add(q).ok());
    }
    REQUIRE(book->remove(6).ok());  // K1AF
  }
  ~PageBook() {
    book.reset();
    fs::remove_all(dir);
  }
};

std::vector<std::string> calls_of(const std::vector<Qso>& qs) {
  std::vector<std::string> out;
  for (const auto& q : qs) out.push_back(q.call);
  return out;
}
}  // namespace

TEST_CASE("log pages: two at a time, the pages joined are list() in order, none repeated at a tie") {
  PageBook b;
  std::vector<std::string> joined;
  std::vector<std::size_t> sizes;
  Cursor c;
  for (int guard = 0; guard < 10; ++guard) {
    const Page p = read_page(*b.book, 0, c, 2);
    sizes.push_back(p.qsos.size());
    for (const auto& q : p.qsos) joined.push_back(q.call);
    if (!p.next) break;
    c = *parse_cursor(*p.next);
  }
  CHECK(joined == std::vector<std::string>{"K1AB", "K1AC", "K1AD", "K1AE", "K1AA", "K1AG"});
  CHECK(joined == calls_of(b.book->list(0)));
  CHECK(sizes == std::vector<std::size_t>{2, 2, 2, 0});  // a full last page: one more, empty, ends it
  // since, and the cursor of the first page at 200 s: it ends between two QSOs of the same second.
  const Page p = read_page(*b.book, 1796160200, Cursor{}, 2);
  CHECK(calls_of(p.qsos) == std::vector<std::string>{"K1AC", "K1AD"});
  REQUIRE(p.next);
  CHECK(*p.next == "1796160200.4");
  CHECK(calls_of(read_page(*b.book, 1796160200, *parse_cursor(*p.next), 10).qsos) ==
        std::vector<std::string>{"K1AE", "K1AA", "K1AG"});
  CHECK(!read_page(*b.book, 1796160200, *parse_cursor(*p.next), 10).next);
}

TEST_CASE("log pages: the cursor's text, and what is not one") {
  CHECK(parse_cursor("1796161460.42")->time_on == 1796161460);
  CHECK(parse_cursor("1796161460.42")->id == 42);
  CHECK(parse_cursor("-5.0")->time_on == -5);
  for (const char* bad : {"", ".", "12", "12.", ".3", "1.2.3", "a.1", "1.b", "1 .2", "99999999999999999999.1"})
    CHECK_MESSAGE(!parse_cursor(bad), bad);
}

TEST_CASE("log pages: the ADIF pages joined are write_adif's export of the whole log") {
  PageBook b;
  std::string joined;
  std::vector<std::string> warnings;
  Cursor c;
  bool first = true;
  for (int guard = 0; guard < 10; ++guard) {
    const Page p = read_page(*b.book, 0, c, 3);
    joined += adif_page(p.qsos, first, "9.9", 1796161460, warnings);
    first = false;
    if (!p.next) break;
    c = *parse_cursor(*p.next);
  }
  const AdifExport whole = write_adif(b.book->list(0), "9.9", 1796161460);
  CHECK(joined == whole.text);
  CHECK(warnings == whole.warnings);
  CHECK(read_adif(joined).qsos.size() == 6);
}
