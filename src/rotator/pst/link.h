// A box that speaks PstRotator's UDP protocol as trakbox's rotator (--rotator pstrotator:HOST[:PORT]):
// PstRotator itself driving its controller, a CSN Technologies S.A.T. The commands go to HOST:PORT
// (12000 by default); the box answers to this computer's port PORT+1 (12001), which the link binds.
// Read back: every poll asks AZ? and EL? and the link is connected only once the box has answered
// both (rotator/worker.h: connected means answering); a box that stops answering is a lost link.
#pragma once
#include <chrono>
#include <string>

#include "rotator/worker.h"

namespace tb::rotator {

struct PstRotatorOptions {
  std::string host;
  int port = 12000;
  std::chrono::milliseconds poll{500};
  std::chrono::milliseconds io_timeout{1000};
  std::chrono::milliseconds backoff_min{250};
  std::chrono::milliseconds backoff_max{8000};
};

class PstRotator final : public WorkerRotator {
 public:
  explicit PstRotator(const PstRotatorOptions& options);
};

}  // namespace tb::rotator
