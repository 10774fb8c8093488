#include <doctest/doctest.h>
#include <sqlite3.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>

#include "logbook/logbook.h"
#include "support/qso_samples.h"

using namespace tb::logbook;
namespace fs = std::filesystem;

namespace {
struct TempBook {
  fs::path dir;
  TempBook() {
    static int n = 0;
    dir = fs::temp_directory_path() / ("trakbox-logbook-" + std::to_string(::getpid()) + "-" + std::to_string(++n));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  ~TempBook() { fs::remove_all(dir); }
  std::string path() const { return (dir / "logbook.sqlite").string(); }
};

// The shared sample without its id (the logbook gives one).
Qso unsaved_rs44() {
  Qso q = tb::testing::rs44_qso();
  q.id = 0;
  return q;
}
}  // namespace

TEST_CASE("A QSO is stored with every field, survives reopening, and the schema is version 2") {
  TempBook t;
  std::string err;
  {
    auto book = Logbook::open(t.path(), err);
    REQUIRE_MESSAGE(book, err);
    const Added a = book->add(unsaved_rs44());
    REQUIRE_MESSAGE(a.ok(), a.error);
    CHECK(a.id == 1);
  }
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  const auto q = book->get(1);
  REQUIRE(q);
  Qso want = unsaved_rs44();
  want.id = 1;
  want.band = "2m";
  want.band_rx = "70cm";
  CHECK(*q == want);
  CHECK(book->count() == 1);
  CHECK(book->last()->call == "W1AW");
  CHECK(fs::exists(t.dir / "logbook.sqlite-wal"));
}

TEST_CASE("A bad record is refused naming the field and nothing is stored") {
  TempBook t;
  std::string err;
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  Qso q = unsaved_rs44();
  q.grid = "FN3";
  const Added a = book->add(q);
  CHECK_FALSE(a.ok());
  CHECK(a.error.rfind("grid: 'FN3'", 0) == 0);
  CHECK(book->count() == 0);
}

TEST_CASE("An edit keeps the previous version; delete is a mark with a version of its own") {
  TempBook t;
  std::string err;
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  REQUIRE(book->add(unsaved_rs44()).ok());
  Qso changed = unsaved_rs44();
  changed.grid = "FN42";
  changed.source = Source::cli;  // the source of a record stays the one it was made by
  REQUIRE(book->edit(1, changed).ok());
  auto now = book->get(1);
  REQUIRE(now);
  CHECK(now->grid == "FN42");
  CHECK(now->version == 2);
  CHECK(now->source == Source::web);
  auto old = book->versions(1);
  REQUIRE(old.size() == 1);
  CHECK(old[0].grid == "FN31");
  CHECK(old[0].version == 1);
  REQUIRE(book->remove(1).ok());
  CHECK(book->count() == 0);
  CHECK(book->list().empty());
  REQUIRE(book->list(0, true).size() == 1);
  CHECK(book->list(0, true)[0].deleted);
  CHECK(book->versions(1).size() == 2);
  CHECK(book->remove(1).error == "id: no QSO 1 in the log");
  CHECK(book->edit(7, unsaved_rs44()).error == "id: no QSO 7 in the log");
}

TEST_CASE("Import stores all or nothing and recognises duplicates") {
  TempBook t;
  std::string err;
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  REQUIRE(book->add(unsaved_rs44()).ok());
  Qso other = unsaved_rs44();
  other.call = "K1JT";
  Qso bad = unsaved_rs44();
  bad.call = "K1 JT";
  const Imported refused = book->import({other, bad});
  CHECK(refused.error == "record 2: call: 'K1 JT' is not a callsign (letters, digits and '/' only)");
  CHECK(book->count() == 1);
  const Imported r = book->import({unsaved_rs44(), other, other});
  CHECK(r.error.empty());
  CHECK(r.added == 1);
  CHECK(r.duplicates == 2);
  CHECK(book->count() == 2);
}

TEST_CASE("The upload queue is on disk: it is there after reopening until marked done") {
  TempBook t;
  std::string err;
  {
    auto book = Logbook::open(t.path(), err);
    REQUIRE(book);
    REQUIRE(book->add(unsaved_rs44(), true).ok());
    book->upload_failed(1, 1796161520, "logger: connection refused");
  }
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  const auto q = book->upload_queue();
  REQUIRE(q.size() == 1);
  CHECK(q[0].qso_id == 1);
  CHECK(q[0].attempts == 1);
  CHECK(q[0].next_try == 1796161520);
  CHECK(q[0].last_error == "logger: connection refused");
  book->upload_done(1);
  CHECK(book->upload_queue_length() == 0);
}

TEST_CASE("A logbook of a newer schema is refused, not changed") {
  TempBook t;
  std::string err;
  REQUIRE(Logbook::open(t.path(), err));
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(t.path().c_str(), &db) == SQLITE_OK);
  CHECK(sqlite3_exec(db, "PRAGMA user_version = 99", nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
  CHECK_FALSE(Logbook::open(t.path(), err));
  CHECK(err == t.path() + ": its schema version 99 is newer than this trakbox's (2)");
}

// Issue 59: version 2 adds SUBMODE (FT4 is MFSK's). A version-1 logbook, made here with version 1's
// tables, gains the column when opened: its QSOs keep every field with no submode, and new ones
// (and their edits' kept versions) carry theirs.
TEST_CASE("A version-1 logbook gains the submode column; its QSOs keep their fields") {
  TempBook t;
  const char* v1 =
      "CREATE TABLE qso (id INTEGER NOT NULL, version INTEGER NOT NULL, deleted INTEGER NOT NULL DEFAULT 0, "
      "call TEXT NOT NULL, grid TEXT NOT NULL, rst_sent TEXT NOT NULL, rst_rcvd TEXT NOT NULL, "
      "time_on INTEGER NOT NULL, sat_name TEXT NOT NULL, lotw_name TEXT NOT NULL, norad INTEGER NOT NULL, "
      "mode TEXT NOT NULL, uplink_hz INTEGER NOT NULL, downlink_hz INTEGER NOT NULL, "
      "uplink_tuned_hz INTEGER NOT NULL, downlink_tuned_hz INTEGER NOT NULL, band TEXT NOT NULL, "
      "band_rx TEXT NOT NULL, my_grid TEXT NOT NULL, station_call TEXT NOT NULL, power_w REAL NOT NULL, "
      "note TEXT NOT NULL, source TEXT NOT NULL, PRIMARY KEY (id)); CREATE INDEX qso_time ON qso (time_on); "
      "CREATE TABLE qso_version AS SELECT * FROM qso WHERE 0; "
      "CREATE TABLE upload_queue (qso_id INTEGER PRIMARY KEY, attempts INTEGER NOT NULL DEFAULT 0, "
      "next_try INTEGER NOT NULL DEFAULT 0, last_error TEXT NOT NULL DEFAULT ''); "
      "INSERT INTO qso VALUES (1, 1, 0, 'W1AW', 'FN31', '59', '57', 1796161460, 'RS-44', 'RS-44', 44909, 'SSB', "
      "145965000, 435640000, 145962310, 435648070, '2m', '70cm', '', 'WA7GXD', 2.5, 'first', 'web'); "
      "PRAGMA user_version = 1;";
  sqlite3* db = nullptr;
  REQUIRE(sqlite3_open(t.path().c_str(), &db) == SQLITE_OK);
  REQUIRE(sqlite3_exec(db, v1, nullptr, nullptr, nullptr) == SQLITE_OK);
  sqlite3_close(db);
  std::string err;
  {
    auto book = Logbook::open(t.path(), err);
    REQUIRE_MESSAGE(book, err);
    const auto old = book->get(1);
    REQUIRE(old);
    CHECK(old->call == "W1AW");
    CHECK(old->mode == "SSB");
    CHECK(old->submode.empty());
    CHECK(old->downlink_tuned_hz == 435'648'070);
    CHECK(old->power_w == 2.5);
    Qso ft4 = unsaved_rs44();
    ft4.mode = "MFSK";
    ft4.submode = "FT4";
    const Added a = book->add(ft4);
    REQUIRE_MESSAGE(a.ok(), a.error);
    ft4.note = "edited";
    REQUIRE(book->edit(a.id, ft4).ok());
  }
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  const auto q = book->get(2);
  REQUIRE(q);
  CHECK(q->mode == "MFSK");
  CHECK(q->submode == "FT4");
  CHECK(q->note == "edited");
  CHECK(book->versions(2).front().submode == "FT4");
  sqlite3* check = nullptr;
  REQUIRE(sqlite3_open(t.path().c_str(), &check) == SQLITE_OK);
  sqlite3_stmt* v = nullptr;
  REQUIRE(sqlite3_prepare_v2(check, "PRAGMA user_version", -1, &v, nullptr) == SQLITE_OK);
  REQUIRE(sqlite3_step(v) == SQLITE_ROW);
  CHECK(sqlite3_column_int(v, 0) == 2);
  sqlite3_finalize(v);
  sqlite3_close(check);
}

// Issue 56 item 12: logbook.sqlite was opened through a symbolic link, the QSO (and -wal, -shm)
// written outside the state directory.
TEST_CASE("A logbook that is a symbolic link (or whose -wal is) is refused, never followed") {
  TempBook t;
  const fs::path outside = t.dir / "outside";
  fs::create_directories(outside);
  fs::create_symlink(outside / "elsewhere.sqlite", t.path());
  std::string err;
  CHECK_FALSE(Logbook::open(t.path(), err));
  CHECK(err == t.path() + ": is a symbolic link: trakbox does not follow links in its state directory; move the "
                          "logbook there as a file");
  CHECK_FALSE(fs::exists(outside / "elsewhere.sqlite"));
  CHECK_FALSE(fs::exists(outside / "elsewhere.sqlite-wal"));
  // A link to a logbook that exists is refused the same, and the target is left as it was.
  fs::remove(t.path());
  {
    std::string e;
    REQUIRE(Logbook::open((outside / "real.sqlite").string(), e));
  }
  const auto size = fs::file_size(outside / "real.sqlite");
  fs::create_symlink(outside / "real.sqlite", t.path());
  CHECK_FALSE(Logbook::open(t.path(), err));
  CHECK(err.find("is a symbolic link") != std::string::npos);
  CHECK(fs::file_size(outside / "real.sqlite") == size);
  // The file itself, its -wal a link: refused naming the -wal.
  fs::remove(t.path());
  fs::create_symlink(outside / "stolen-wal", t.path() + "-wal");
  CHECK_FALSE(Logbook::open(t.path(), err));
  CHECK(err == t.path() + "-wal: is a symbolic link: trakbox does not follow links in its state directory; move "
                          "the logbook there as a file");
  CHECK_FALSE(fs::exists(outside / "stolen-wal"));
}

TEST_CASE("The cost of one insert with synchronous=FULL (one transaction, fsync in WAL)") {
  TempBook t;
  std::string err;
  auto book = Logbook::open(t.path(), err);
  REQUIRE(book);
  const auto t0 = std::chrono::steady_clock::now();
  constexpr int kN = 20;
  for (int i = 0; i < kN; ++i) {
    Qso q = unsaved_rs44();
    q.time_on += i;
    REQUIRE(book->add(q).ok());
  }
  const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count() / kN;
  MESSAGE("one QSO insert: " << ms << " ms");
  CHECK(book->count() == kN);
}
