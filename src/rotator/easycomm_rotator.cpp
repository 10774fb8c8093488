#include "rotator/easycomm_rotator.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <optional>

#include "rotator/serial_line.h"

namespace tb::rotator {

namespace {

int baud_of(const EasycommOptions& o) { return o.baud > 0 ? o.baud : easycomm::default_baud(o.version); }

Drive drive_of(double delta) {
  if (delta > 0.05) return Drive::increase;
  if (delta < -0.05) return Drive::decrease;
  return Drive::stop;
}

class EasycommLink final : public RotatorLink {
 public:
  explicit EasycommLink(EasycommOptions o) : o_(std::move(o)) {}
  ~EasycommLink() override { close(); }

  bool open(std::string& error) override {
    last_.reset();
    return line_.open(o_.device, baud_of(o_), error);
  }
  void close() override { line_.close(); }

  bool stop(std::string& error) override { return line_.write(easycomm::stop(), o_.io_timeout, error); }

  bool go_to(AzEl p, std::optional<std::string>&, std::string& error) override {
    return line_.write(easycomm::set_position(p), o_.io_timeout, error);
  }

  bool poll(LinkReport& report, std::string& error) override {
    // What came in unasked first (an alarm, the SatNOGS firmware's answer to a stop), then the query.
    while (auto l = line_.read_line(std::chrono::milliseconds(0), error)) take(*l, report);
    if (!error.empty()) return false;
    if (!line_.write(easycomm::read_position(), o_.io_timeout, error)) return false;
    const auto until = std::chrono::steady_clock::now() + o_.io_timeout;
    std::string bad;
    while (true) {
      const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(until - std::chrono::steady_clock::now());
      auto l = line_.read_line(std::max(left, std::chrono::milliseconds(0)), error);
      if (!l) {
        if (error.empty())
          error = "no reply to \"AZ EL\" within " + std::to_string(o_.io_timeout.count()) + " ms" +
                  (bad.empty() ? std::string() : " (" + bad + ")");
        return false;
      }
      if (take(*l, report)) return true;
      const auto parsed = easycomm::parse_line(*l);
      if (parsed.kind == easycomm::Line::Kind::bad) bad = parsed.text;
    }
  }

  std::string peer() const override {
    return "the Easycomm " + std::string(o_.version == easycomm::Version::three ? "III" : "II") + " rotator on " +
           o_.device + " at " + std::to_string(baud_of(o_)) + " baud";
  }

 private:
  // One line: a position (true) or an alarm goes into the report; anything else is skipped.
  bool take(const std::string& text, LinkReport& report) {
    const easycomm::Line l = easycomm::parse_line(text);
    if (l.kind == easycomm::Line::Kind::alarm) report.alarm = l.text;
    if (l.kind != easycomm::Line::Kind::position) return false;
    if (last_) report.motion = AxisMotion{drive_of(l.position.az - last_->az), drive_of(l.position.el - last_->el)};
    report.position = l.position;
    last_ = l.position;
    return true;
  }

  const EasycommOptions o_;
  SerialLine line_;
  std::optional<AzEl> last_;
};

}  // namespace

std::string easycomm_label(const EasycommOptions& o) {
  return std::string("Easycomm ") + (o.version == easycomm::Version::three ? "III" : "II") + " on " + o.device +
         " at " + std::to_string(baud_of(o)) + " baud";
}

EasycommRotator::EasycommRotator(const EasycommOptions& o)
    : WorkerRotator(easycomm_label(o), std::make_unique<EasycommLink>(o), {o.poll, o.io_timeout, o.backoff_min, o.backoff_max}) {}

}  // namespace tb::rotator
