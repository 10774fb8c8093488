// Recording a pass (issue 59): which satellites --record-satellites takes, and the file name GQRX's
// audio recorder gives: GQRX's DockAudio::on_audioRecButton_clicked names it
// QDateTime::currentDateTime().toUTC().toString("gqrx_yyyyMMdd_hhmmss") + "_" + the receiver's
// frequency in Hz + ".wav".
#include <doctest/doctest.h>

#include "tracker/recording.h"

using namespace tb;

TEST_CASE("records_satellite: off records nothing; empty list every satellite; names case and blanks aside") {
  radio::RadioConfig c;
  CHECK_FALSE(tracker::records_satellite(c, "SO-50"));
  c.record = radio::Record::audio;
  CHECK(tracker::records_satellite(c, "SO-50"));
  c.record_satellites = " iss , so-50";
  CHECK(tracker::records_satellite(c, "SO-50"));
  CHECK(tracker::records_satellite(c, "ISS"));
  CHECK_FALSE(tracker::records_satellite(c, "RS-44"));
  CHECK_FALSE(tracker::records_satellite(c, "SO-5"));
}

TEST_CASE("recording_file_name: GQRX's audio file from the start in UTC and the frequency; none it cannot know") {
  const orbit::UtcTime t = orbit::from_civil(2026, 5, 21, 14, 10, 2.7);
  CHECK(tracker::recording_file_name("GQRX", radio::Record::audio, t, 436'795'000) ==
        "gqrx_20260521_141002_436795000.wav");
  // The second is cut, never rounded up to 60.
  CHECK(tracker::recording_file_name("GQRX", radio::Record::audio, orbit::from_civil(2026, 12, 31, 23, 59, 59.9996),
                                     145'825'000) == "gqrx_20261231_235959_145825000.wav");
  CHECK(tracker::recording_file_name("SDR++", radio::Record::audio, t, 436'795'000).empty());
  CHECK(tracker::recording_file_name("GQRX", radio::Record::iq, t, 436'795'000).empty());
}
