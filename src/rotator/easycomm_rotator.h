// An Easycomm II or III controller on a serial port, natively (--rotator easycomm3:DEV[:BAUD],
// easycomm2:DEV[:BAUD]): the SatNOGS rotator firmware, SARCNET, the REF interfaces, K3NG. The bytes
// are rotator/easycomm.h's (Hamlib's for set, read and stop). The worker thread (worker.h) polls
// the position every `poll`; a reply that is not a position is skipped (a garbled line is a local
// fault: the next poll asks again), only a silence or a port that hangs up loses the link; an
// unsolicited "AL..." line is reported as the controller's alarm.
#pragma once
#include <chrono>
#include <string>

#include "rotator/easycomm.h"
#include "rotator/worker.h"

namespace tb::rotator {

struct EasycommOptions {
  easycomm::Version version = easycomm::Version::three;
  std::string device;
  int baud = 0;                                  // 0: easycomm::default_baud(version)
  std::chrono::milliseconds poll{250};
  std::chrono::milliseconds io_timeout{500};     // one answer to "AZ EL" (Hamlib waits 200 ms, 3 tries)
  std::chrono::milliseconds backoff_min{250};
  std::chrono::milliseconds backoff_max{8000};
};

class EasycommRotator final : public WorkerRotator {
 public:
  explicit EasycommRotator(const EasycommOptions& options);
};

// "Easycomm III on /dev/ttyUSB0 at 19200 baud"
std::string easycomm_label(const EasycommOptions& options);

}  // namespace tb::rotator
