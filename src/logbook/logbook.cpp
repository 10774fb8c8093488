#include "logbook/logbook.h"

#include <sys/stat.h>

#include <sqlite3.h>

#include <set>

namespace tb::logbook {
namespace {

// The record's columns, in the order of both tables (qso_version is qso's rows as they were).
constexpr const char* kColumns =
    "id, version, deleted, call, grid, rst_sent, rst_rcvd, time_on, sat_name, lotw_name, norad, mode, "
    "uplink_hz, downlink_hz, uplink_tuned_hz, downlink_tuned_hz, band, band_rx, my_grid, station_call, "
    "power_w, note, source, submode";

constexpr const char* kRecordColumns =
    "id INTEGER NOT NULL, version INTEGER NOT NULL, deleted INTEGER NOT NULL DEFAULT 0, "
    "call TEXT NOT NULL, grid TEXT NOT NULL, rst_sent TEXT NOT NULL, rst_rcvd TEXT NOT NULL, "
    "time_on INTEGER NOT NULL, sat_name TEXT NOT NULL, lotw_name TEXT NOT NULL, norad INTEGER NOT NULL, "
    "mode TEXT NOT NULL, uplink_hz INTEGER NOT NULL, downlink_hz INTEGER NOT NULL, "
    "uplink_tuned_hz INTEGER NOT NULL, downlink_tuned_hz INTEGER NOT NULL, band TEXT NOT NULL, "
    "band_rx TEXT NOT NULL, my_grid TEXT NOT NULL, station_call TEXT NOT NULL, power_w REAL NOT NULL, "
    "note TEXT NOT NULL, source TEXT NOT NULL, submode TEXT NOT NULL DEFAULT ''";

// One prepared statement, finalized at the end of its scope.
class Stmt {
 public:
  Stmt(sqlite3* db, const std::string& sql) { sqlite3_prepare_v2(db, sql.c_str(), -1, &s_, nullptr); }
  ~Stmt() { sqlite3_finalize(s_); }
  Stmt(const Stmt&) = delete;
  Stmt& operator=(const Stmt&) = delete;
  bool ok() const { return s_ != nullptr; }
  Stmt& bind(int i, std::int64_t v) { sqlite3_bind_int64(s_, i, v); return *this; }
  Stmt& bind(int i, double v) { sqlite3_bind_double(s_, i, v); return *this; }
  Stmt& bind(int i, const std::string& v) {
    sqlite3_bind_text(s_, i, v.data(), static_cast<int>(v.size()), SQLITE_TRANSIENT);
    return *this;
  }
  int step() { return s_ ? sqlite3_step(s_) : SQLITE_ERROR; }
  void reset() { sqlite3_reset(s_); }  // to step it again with new bindings
  std::int64_t i64(int c) const { return sqlite3_column_int64(s_, c); }
  double real(int c) const { return sqlite3_column_double(s_, c); }
  std::string str(int c) const {
    const auto* t = sqlite3_column_text(s_, c);
    return t ? std::string(reinterpret_cast<const char*>(t), static_cast<std::size_t>(sqlite3_column_bytes(s_, c)))
             : std::string();
  }

 private:
  sqlite3_stmt* s_ = nullptr;
};

// The record's text and integer fields by their column in kColumns (parameter column + 1 in
// kInsert): one table for reading a row and for binding one.
struct TextColumn {
  int column;
  std::string Qso::*field;
};
constexpr TextColumn kTextColumns[] = {
    {3, &Qso::call},      {4, &Qso::grid},     {5, &Qso::rst_sent}, {6, &Qso::rst_rcvd},
    {8, &Qso::sat_name},  {9, &Qso::lotw_name}, {11, &Qso::mode},    {16, &Qso::band},
    {17, &Qso::band_rx},  {18, &Qso::my_grid},  {19, &Qso::station_call}, {21, &Qso::note},
    {23, &Qso::submode}};
struct IntColumn {
  int column;
  std::int64_t Qso::*field;
};
constexpr IntColumn kIntColumns[] = {{7, &Qso::time_on},          {12, &Qso::uplink_hz},
                                     {13, &Qso::downlink_hz},     {14, &Qso::uplink_tuned_hz},
                                     {15, &Qso::downlink_tuned_hz}};

Qso read_row(const Stmt& s) {
  Qso q;
  q.id = s.i64(0);
  q.version = static_cast<int>(s.i64(1));
  q.deleted = s.i64(2) != 0;
  for (const auto& c : kTextColumns) q.*c.field = s.str(c.column);
  for (const auto& c : kIntColumns) q.*c.field = s.i64(c.column);
  q.norad = static_cast<int>(s.i64(10));
  q.power_w = s.real(20);
  q.source = source_from_name(s.str(22)).value_or(Source::import);
  return q;
}

// Binds the record's fields from column 2 (version) on as parameters 2..24; parameter 1 is the id.
void bind_record(Stmt& s, const Qso& q) {
  s.bind(2, std::int64_t{q.version}).bind(3, std::int64_t{q.deleted});
  for (const auto& c : kTextColumns) s.bind(c.column + 1, q.*c.field);
  for (const auto& c : kIntColumns) s.bind(c.column + 1, q.*c.field);
  s.bind(11, std::int64_t{q.norad}).bind(21, q.power_w).bind(23, std::string(source_name(q.source)));
}

const std::string kInsert = std::string("INSERT INTO qso (") + kColumns +
                            ") VALUES (?1,?2,?3,?4,?5,?6,?7,?8,?9,?10,?11,?12,?13,?14,?15,?16,?17,?18,?19,?20,?21,?22,?23,?24)";

}  // namespace

Logbook::Logbook(sqlite3* db) : db_(db) {}
Logbook::~Logbook() { sqlite3_close(db_); }

bool Logbook::exec(const char* sql, std::string* error) const {
  char* msg = nullptr;
  if (sqlite3_exec(db_, sql, nullptr, nullptr, &msg) == SQLITE_OK) return true;
  if (error) *error = msg ? msg : sqlite3_errmsg(db_);
  sqlite3_free(msg);
  return false;
}

bool Logbook::migrate(std::string& error) {
  Stmt v(db_, "PRAGMA user_version");
  int version = v.step() == SQLITE_ROW ? static_cast<int>(v.i64(0)) : -1;
  if (version < 0) return error = "cannot read its schema version", false;
  if (version > kSchemaVersion)
    return error = "its schema version " + std::to_string(version) + " is newer than this trakbox's (" +
                   std::to_string(kSchemaVersion) + ")",
           false;
  if (version == 0) {
    const std::string create =
        std::string("BEGIN IMMEDIATE; CREATE TABLE qso (") + kRecordColumns +
        ", PRIMARY KEY (id)); CREATE INDEX qso_time ON qso (time_on); CREATE TABLE qso_version (" +
        kRecordColumns + ", PRIMARY KEY (id, version)); CREATE TABLE upload_queue (qso_id INTEGER PRIMARY KEY, "
        "attempts INTEGER NOT NULL DEFAULT 0, next_try INTEGER NOT NULL DEFAULT 0, last_error TEXT NOT NULL "
        "DEFAULT ''); PRAGMA user_version = 2; COMMIT;";
    if (!exec(create.c_str(), &error)) {
      exec("ROLLBACK");
      return false;
    }
    return true;
  }
  // Version 1 had no SUBMODE (issue 59: FT4 is MFSK's): its QSOs have none.
  if (version == 1 &&
      !exec("BEGIN IMMEDIATE; ALTER TABLE qso ADD COLUMN submode TEXT NOT NULL DEFAULT ''; ALTER TABLE qso_version "
            "ADD COLUMN submode TEXT NOT NULL DEFAULT ''; PRAGMA user_version = 2; COMMIT;",
            &error)) {
    exec("ROLLBACK");
    return false;
  }
  return true;
}

std::unique_ptr<Logbook> Logbook::open(const std::string& path, std::string& error) {
  // A link is never followed (docs/security.md): the file, and its -wal and -shm beside it, would
  // be written wherever the link points. Looked at first for a clear refusal; SQLITE_OPEN_NOFOLLOW
  // holds against a link made between the look and the open.
  constexpr const char* kLink = "is a symbolic link: trakbox does not follow links in its state directory; "
                                "move the logbook there as a file";
  for (const char* suffix : {"", "-wal", "-shm"}) {
    struct stat st {};
    if (::lstat((path + suffix).c_str(), &st) == 0 && S_ISLNK(st.st_mode)) {
      error = path + suffix + ": " + kLink;
      return nullptr;
    }
  }
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db,
                      SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_NOMUTEX | SQLITE_OPEN_NOFOLLOW,
                      nullptr) != SQLITE_OK) {
    error = path + ": " + (db && sqlite3_extended_errcode(db) == SQLITE_CANTOPEN_SYMLINK ? kLink
                           : db                                                     ? sqlite3_errmsg(db)
                                                                                    : "cannot open");
    sqlite3_close(db);
    return nullptr;
  }
  std::unique_ptr<Logbook> book(new Logbook(db));
  sqlite3_busy_timeout(db, 2000);
  std::string why;
  // The schema is made (or migrated) without waiting for the disk: WAL keeps the file whole either
  // way, and a creation or migration a power cut takes back is made again at the next open. Every
  // QSO after it is synchronous=FULL. (A fresh file's fsyncs cost 20 to 40 ms at the station's start,
  // before its first tick: AOS events at the clock's start came late, integ_service_events.)
  if (!book->exec("PRAGMA synchronous=NORMAL; PRAGMA journal_mode=WAL; PRAGMA foreign_keys=ON;", &why) ||
      !book->migrate(why) || !book->exec("PRAGMA synchronous=FULL;", &why)) {
    error = path + ": " + why;
    return nullptr;
  }
  return book;
}

Added Logbook::add(Qso q, bool queue_upload) {
  q = normalized(std::move(q));
  q.version = 1;
  q.deleted = false;
  if (auto e = check_qso(q)) return {0, *e};
  if (!exec("BEGIN IMMEDIATE")) return {0, std::string("logbook: ") + sqlite3_errmsg(db_)};
  Stmt next(db_, "SELECT COALESCE(MAX(id), 0) + 1 FROM qso");
  q.id = next.step() == SQLITE_ROW ? next.i64(0) : 1;
  Stmt ins(db_, kInsert);
  ins.bind(1, q.id);
  bind_record(ins, q);
  bool ok = ins.step() == SQLITE_DONE;
  if (ok && queue_upload) {
    Stmt qu(db_, "INSERT OR IGNORE INTO upload_queue (qso_id) VALUES (?1)");
    ok = qu.bind(1, q.id).step() == SQLITE_DONE;
  }
  std::string why;
  if (ok && exec("COMMIT", &why)) return {q.id, {}};
  if (why.empty()) why = sqlite3_errmsg(db_);
  exec("ROLLBACK");
  return {0, "logbook: " + why};
}

Added Logbook::edit(std::int64_t id, Qso q) {
  const auto old = get(id);
  if (!old) return {0, "id: no QSO " + std::to_string(id) + " in the log"};
  q = normalized(std::move(q));
  if (auto e = check_qso(q)) return {0, *e};
  q.id = id;
  q.version = old->version + 1;
  q.source = old->source;
  if (!exec("BEGIN IMMEDIATE")) return {0, std::string("logbook: ") + sqlite3_errmsg(db_)};
  Stmt keep(db_, std::string("INSERT INTO qso_version SELECT ") + kColumns + " FROM qso WHERE id = ?1");
  bool ok = keep.bind(1, id).step() == SQLITE_DONE;
  Stmt del(db_, "DELETE FROM qso WHERE id = ?1");
  ok = ok && del.bind(1, id).step() == SQLITE_DONE;
  Stmt ins(db_, kInsert);
  ins.bind(1, id);
  bind_record(ins, q);
  ok = ok && ins.step() == SQLITE_DONE;
  std::string why;
  if (ok && exec("COMMIT", &why)) return {id, {}};
  if (why.empty()) why = sqlite3_errmsg(db_);
  exec("ROLLBACK");
  return {0, "logbook: " + why};
}

Added Logbook::remove(std::int64_t id) {
  auto q = get(id);
  if (!q || q->deleted) return {0, "id: no QSO " + std::to_string(id) + " in the log"};
  q->deleted = true;
  if (!exec("BEGIN IMMEDIATE")) return {0, std::string("logbook: ") + sqlite3_errmsg(db_)};
  Stmt keep(db_, std::string("INSERT INTO qso_version SELECT ") + kColumns + " FROM qso WHERE id = ?1");
  bool ok = keep.bind(1, id).step() == SQLITE_DONE;
  Stmt mark(db_, "UPDATE qso SET deleted = 1, version = version + 1 WHERE id = ?1");
  ok = ok && mark.bind(1, id).step() == SQLITE_DONE;
  std::string why;
  if (ok && exec("COMMIT", &why)) return {id, {}};
  if (why.empty()) why = sqlite3_errmsg(db_);
  exec("ROLLBACK");
  return {0, "logbook: " + why};
}

std::optional<Qso> Logbook::get(std::int64_t id) const {
  Stmt s(db_, std::string("SELECT ") + kColumns + " FROM qso WHERE id = ?1");
  if (s.bind(1, id).step() != SQLITE_ROW) return std::nullopt;
  return read_row(s);
}

std::vector<Qso> Logbook::list(std::int64_t since, bool with_deleted) const {
  Stmt s(db_, std::string("SELECT ") + kColumns + " FROM qso WHERE time_on >= ?1" +
                  (with_deleted ? "" : " AND deleted = 0") + " ORDER BY time_on, id");
  s.bind(1, since);
  std::vector<Qso> out;
  while (s.step() == SQLITE_ROW) out.push_back(read_row(s));
  return out;
}

std::vector<Qso> Logbook::page(std::int64_t since, std::int64_t after_time, std::int64_t after_id,
                               std::size_t limit) const {
  Stmt s(db_, std::string("SELECT ") + kColumns +
                  " FROM qso WHERE time_on >= ?1 AND deleted = 0 AND (time_on, id) > (?2, ?3) ORDER BY time_on, id LIMIT ?4");
  s.bind(1, since).bind(2, after_time).bind(3, after_id).bind(4, static_cast<std::int64_t>(limit));
  std::vector<Qso> out;
  while (s.step() == SQLITE_ROW) out.push_back(read_row(s));
  return out;
}

std::string Logbook::path() const {
  const char* f = sqlite3_db_filename(db_, "main");
  return f ? std::string(f) : std::string();
}

std::vector<Qso> Logbook::versions(std::int64_t id) const {
  Stmt s(db_, std::string("SELECT ") + kColumns + " FROM qso_version WHERE id = ?1 ORDER BY version");
  s.bind(1, id);
  std::vector<Qso> out;
  while (s.step() == SQLITE_ROW) out.push_back(read_row(s));
  return out;
}

std::size_t Logbook::count() const {
  Stmt s(db_, "SELECT COUNT(*) FROM qso WHERE deleted = 0");
  return s.step() == SQLITE_ROW ? static_cast<std::size_t>(s.i64(0)) : 0;
}

std::optional<Qso> Logbook::last() const {
  Stmt s(db_, std::string("SELECT ") + kColumns + " FROM qso WHERE deleted = 0 ORDER BY time_on DESC, id DESC LIMIT 1");
  if (s.step() != SQLITE_ROW) return std::nullopt;
  return read_row(s);
}

std::string Logbook::duplicate_key(const Qso& q) {
  const std::string sat = q.lotw_name.empty() ? q.sat_name : q.lotw_name;
  return q.call + "|" + std::to_string(q.time_on) + "|" + sat + "|" + q.band + "|" + q.mode;
}

Imported Logbook::import(const std::vector<Qso>& qsos) {
  Imported r;
  std::set<std::string> seen;
  for (const Qso& q : list(0, false)) seen.insert(duplicate_key(q));
  std::vector<Qso> fresh;
  for (std::size_t i = 0; i < qsos.size(); ++i) {
    Qso q = normalized(qsos[i]);
    if (auto e = check_qso(q)) return {0, 0, "record " + std::to_string(i + 1) + ": " + *e};
    if (!seen.insert(duplicate_key(q)).second) {
      ++r.duplicates;
      continue;
    }
    fresh.push_back(std::move(q));
  }
  if (!exec("BEGIN IMMEDIATE")) return {0, 0, std::string("logbook: ") + sqlite3_errmsg(db_)};
  Stmt next(db_, "SELECT COALESCE(MAX(id), 0) FROM qso");
  std::int64_t id = next.step() == SQLITE_ROW ? next.i64(0) : 0;
  bool ok = true;
  // One statement for all the records: the write transaction (which another connection's writes
  // wait for: an import runs on a worker thread) is as short as it can be.
  Stmt ins(db_, kInsert);
  for (Qso& q : fresh) {
    q.id = ++id;
    q.version = 1;
    q.deleted = false;
    ins.reset();
    ins.bind(1, q.id);
    bind_record(ins, q);
    if (!(ok = ins.step() == SQLITE_DONE)) break;
  }
  std::string why;
  if (ok && exec("COMMIT", &why)) {
    r.added = fresh.size();
    return r;
  }
  if (why.empty()) why = sqlite3_errmsg(db_);
  exec("ROLLBACK");
  return {0, 0, "logbook: " + why};
}

bool Logbook::enqueue_upload(std::int64_t qso_id, std::int64_t now) {
  Stmt s(db_, "INSERT OR IGNORE INTO upload_queue (qso_id, next_try) VALUES (?1, ?2)");
  return s.bind(1, qso_id).bind(2, now).step() == SQLITE_DONE;
}

std::vector<QueuedUpload> Logbook::upload_queue() const {
  Stmt s(db_, "SELECT qso_id, attempts, next_try, last_error FROM upload_queue ORDER BY qso_id");
  std::vector<QueuedUpload> out;
  while (s.step() == SQLITE_ROW)
    out.push_back({s.i64(0), static_cast<int>(s.i64(1)), s.i64(2), s.str(3)});
  return out;
}

void Logbook::upload_done(std::int64_t qso_id) {
  Stmt s(db_, "DELETE FROM upload_queue WHERE qso_id = ?1");
  s.bind(1, qso_id).step();
}

void Logbook::upload_failed(std::int64_t qso_id, std::int64_t next_try, const std::string& why) {
  Stmt s(db_, "UPDATE upload_queue SET attempts = attempts + 1, next_try = ?2, last_error = ?3 WHERE qso_id = ?1");
  s.bind(1, qso_id).bind(2, next_try).bind(3, why).step();
}

std::size_t Logbook::upload_queue_length() const {
  Stmt s(db_, "SELECT COUNT(*) FROM upload_queue");
  return s.step() == SQLITE_ROW ? static_cast<std::size_t>(s.i64(0)) : 0;
}

}  // namespace tb::logbook
