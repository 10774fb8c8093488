#pragma once
// The operator's logbook: SQLite at STATE/logbook.sqlite (WAL, synchronous=FULL), owned by the
// station's loop. Each change is one transaction, committed (on disk) before the call returns, so a
// front end that acknowledges after it has the QSO on disk. Edits keep the previous version (table
// qso_version); delete is a mark. The upload queue of the logger (table upload_queue) lives here
// too, so nothing waiting is lost over a restart. The schema carries its version in
// PRAGMA user_version and is migrated forward on open.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "logbook/qso.h"

struct sqlite3;

namespace tb::logbook {

inline constexpr int kSchemaVersion = 2;  // 2: submode (issue 59)

struct Added {
  std::int64_t id = 0;   // 0 when refused
  std::string error;     // the refusal, naming the field ("call: ...")
  bool ok() const { return error.empty(); }
};

struct Imported {
  std::size_t added = 0, duplicates = 0;
  std::string error;     // nothing stored when set
};

struct QueuedUpload {
  std::int64_t qso_id = 0;
  int attempts = 0;
  std::int64_t next_try = 0;   // UTC seconds
  std::string last_error;
};

class Logbook {
 public:
  // Opens (creating) the file; nullptr and `error` set when it cannot be opened or migrated.
  static std::unique_ptr<Logbook> open(const std::string& path, std::string& error);
  ~Logbook();
  Logbook(const Logbook&) = delete;
  Logbook& operator=(const Logbook&) = delete;

  // Normalises, checks, stores in one transaction; with `queue_upload` also queues it for the
  // logger in the same transaction.
  Added add(Qso q, bool queue_upload = false);
  // Replaces record `id` (its previous version kept); the stored id, version and source stay.
  Added edit(std::int64_t id, Qso q);
  Added remove(std::int64_t id);   // the deletion mark (a version of its own)
  std::optional<Qso> get(std::int64_t id) const;
  // Records with time_on >= since, oldest first; deleted ones only when asked.
  std::vector<Qso> list(std::int64_t since = 0, bool with_deleted = false) const;
  // One page of list() (docs/logbook.md, "Paging"): the records with time_on >= since after the
  // cursor (after_time, after_id) in (time_on, id) order, at most `limit`, deleted ones left out.
  // The first page has the cursor (INT64_MIN, 0); the next starts after the last record returned.
  // Each page is one indexed query, so a caller can read the whole log in bounded pieces.
  std::vector<Qso> page(std::int64_t since, std::int64_t after_time, std::int64_t after_id, std::size_t limit) const;
  // The database file's path ("" for an in-memory one): a worker thread opens its own connection.
  std::string path() const;
  std::vector<Qso> versions(std::int64_t id) const;   // the previous versions, oldest first
  std::size_t count() const;                          // not deleted
  std::optional<Qso> last() const;                    // the latest time on, not deleted
  // All of `qsos` or none: a record equal to one stored (same call, time on, satellite, band and
  // mode) is a duplicate and skipped.
  Imported import(const std::vector<Qso>& qsos);

  // The logger's queue.
  bool enqueue_upload(std::int64_t qso_id, std::int64_t now);
  std::vector<QueuedUpload> upload_queue() const;
  void upload_done(std::int64_t qso_id);
  void upload_failed(std::int64_t qso_id, std::int64_t next_try, const std::string& why);
  std::size_t upload_queue_length() const;

  static std::string duplicate_key(const Qso& q);

 private:
  explicit Logbook(sqlite3* db);
  bool exec(const char* sql, std::string* error = nullptr) const;
  bool migrate(std::string& error);
  sqlite3* db_;
};

}  // namespace tb::logbook
