// A logbook in a temporary directory of its own, with the shipped NORAD to LoTW table, set on a
// simulated station (tracker::LogOps then reaches it), for the tests of the front ends that log:
// host mode's LOG, the web API's log endpoints. A fixture derives from StationFixture first and
// this second, so the logbook is taken off the station before the station goes.
#pragma once
#include <unistd.h>

#include <filesystem>
#include <string>

#include "logbook/lotw_names.h"
#include "test_paths.h"
#include "tracker/log_ops.h"
#include "tracker/station_loop.h"

namespace tb::testing {

struct TempLogbook {
  std::filesystem::path dir;
  tracker::Logging logging;
  tracker::StationLoop* on = nullptr;

  // `name` keeps the directories of test programs that run at once apart.
  void open_logbook(tracker::StationLoop& station, const std::string& name) {
    dir = std::filesystem::temp_directory_path() / ("trakbox-" + name + "-" + std::to_string(::getpid()));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    logging.book = logbook::Logbook::open((dir / "logbook.sqlite").string(), logging.open_error);
    logging.names = logbook::load_lotw_names(std::string(TRAKBOX_SOURCE_DIR) + "/data/lotw-satellites.txt");
    station.set_logging(&logging);
    on = &station;
  }
  TempLogbook() = default;
  TempLogbook(const TempLogbook&) = delete;
  TempLogbook& operator=(const TempLogbook&) = delete;
  ~TempLogbook() {
    if (on) on->set_logging(nullptr);
    logging.book.reset();
    if (!dir.empty()) std::filesystem::remove_all(dir);
  }
};

}  // namespace tb::testing
