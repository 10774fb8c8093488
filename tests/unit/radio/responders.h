// Radios on the far end of a socat pty pair for the radio tests, each written from its documented
// protocol (Icom's IC-9700 CI-V reference; Hamlib's ft847.c and ft817.c; docs/radio.md's TS-2000
// section), with the faults Hamlib's own simulators show (simulators/simic9700.c answers 16 5A with
// a data frame, simic910.c does not answer 1A 07) and a power switch: switched off, a responder
// neither echoes nor answers, and comes back as a radio switched on again (out of satellite mode;
// the FT-847 with its CAT off).
#pragma once
#include <atomic>
#include <map>
#include <mutex>
#include <thread>

#include "radio/cat.h"
#include "radio/factory.h"
#include "support.h"

namespace tbtest {

using namespace tb::radio;
using namespace std::chrono_literals;

// An IC-9700 at A2h (CI-V reference guide): FB/FA answers, 05/06 on the selected band, 07 D0/D1
// selects Main/Sub, 03 answers the selected band's frequency, 1C 03 the transmit frequency (Sub in
// satellite mode), 16 5A satellite mode, 1B 00 tone,
// 16 42 TONE. With echo (a CI-V bus) every frame comes back first; without (USB, Echo Back OFF)
// only the answer. turn() moves a band's dial as the knob would and sends the transceive frame.
class Ic9700 {
 public:
  // Also an IC-9100 (7Ch, satellite mode 16 5A as the IC-9700) or IC-910H (60h, 1A 07).
  Ic9700(const std::string& path, bool echo, std::uint8_t address = 0xA2) : end_(path), echo_(echo), kAddr(address) {
    thread_ = std::thread([this] { run(); });
  }
  ~Ic9700() {
    stop_ = true;
    thread_.join();
  }
  std::atomic<bool> refuse_tone{false};
  std::atomic<bool> refuse_satmode{false};
  // How satellite mode (16 5A / 1A 07) is answered besides FB: Hamlib's simic9700 and simic9100
  // echo the value in a data frame (FE FE E0 A2 16 5A 00 FD), simic910 sends nothing that answers.
  enum class SatAnswer { fb, data, silent };
  std::atomic<SatAnswer> sat_answer{SatAnswer::fb};
  std::atomic<bool> refuse_band{false};      // 07 D0 / D1 (and 07 00 / 01) answered FA
  // 07 D0 / D1 answered FB but not followed; 07 00 / 01 select VFO A / B (kept as Main / Sub), as
  // Hamlib's simic910 does.
  std::atomic<bool> ignore_band_select{false};
  std::atomic<bool> data_for_mode{false};    // 06 answered with a data frame, not FB
  std::atomic<bool> refuse_tx_read{false};   // 1C 03 answered FA (simic9700 falls through to FA)
  // Switched off: no echo, no answer; switched on again: out of satellite mode.
  void power(bool on) {
    std::lock_guard lock(mu_);
    if (on && off_) sat_ = false;
    off_ = !on;
  }

  std::vector<Bytes> frames() {
    std::lock_guard lock(mu_);
    return frames_;
  }
  void clear() {
    std::lock_guard lock(mu_);
    frames_.clear();
  }
  Hz frequency(icom::Band b) {
    std::lock_guard lock(mu_);
    return hz_[b == icom::Band::main ? 0 : 1];
  }
  bool satellite() {
    std::lock_guard lock(mu_);
    return sat_;
  }
  int tone() {
    std::lock_guard lock(mu_);
    return tone_on_ ? tone_ : 0;
  }
  void turn(icom::Band b, Hz delta) {
    std::lock_guard lock(mu_);
    Hz& hz = hz_[b == icom::Band::main ? 0 : 1];
    hz += delta;
    end_.write(icom::frame(0x00, kAddr, 0x00, bcd_little_endian(static_cast<std::uint64_t>(hz), 5)));
  }


 private:
  void answer(bool ok) { end_.write({0xFE, 0xFE, icom::kController, kAddr, ok ? icom::kOk : icom::kNg, 0xFD}); }
  void run() {
    tbtest::read_civ_frames(end_, stop_, [this](const Bytes& frame) { take(frame); });
  }
  void take(const Bytes& raw) {
    std::lock_guard lock(mu_);
    frames_.push_back(raw);
    if (off_) return;
    if (echo_) end_.write(raw);
    const auto f = icom::decode_frame(raw);
    if (!f || f->to != kAddr) return;
    const std::size_t band = selected_main_ ? 0 : 1;
    const auto& d = f->data;
    if (f->cmd == 0x05 && d.size() == 5) {
      hz_[band] = static_cast<Hz>(*decode_bcd_little_endian(d));
      answer(true);
    } else if (f->cmd == 0x06 && data_for_mode) {
      end_.write(icom::frame(icom::kController, kAddr, 0x06, d));
    } else if (f->cmd == 0x06) {
      answer(!d.empty());
    } else if (f->cmd == 0x07 && d.size() == 1 && (d[0] == 0x00 || d[0] == 0x01) && ignore_band_select) {
      selected_main_ = d[0] == 0x00;
      answer(true);
    } else if (f->cmd == 0x07 && d.size() == 1 && (d[0] == 0xD0 || d[0] == 0xD1) && ignore_band_select) {
      answer(true);
    } else if (f->cmd == 0x07 && d.size() == 1 && (d[0] == 0xD0 || d[0] == 0xD1)) {
      if (!refuse_band) selected_main_ = d[0] == 0xD0;
      answer(!refuse_band);
    } else if (f->cmd == 0x1C && refuse_tx_read) {
      answer(false);
    } else if (f->cmd == 0x03 && d.empty()) {
      end_.write(icom::frame(icom::kController, kAddr, 0x03, bcd_little_endian(static_cast<std::uint64_t>(hz_[band]), 5)));
    } else if (f->cmd == 0x1C && d.size() == 1 && d[0] == 0x03) {   // the TX frequency: Sub in satellite mode
      Bytes a{0x03};
      const Bytes bcd = bcd_little_endian(static_cast<std::uint64_t>(hz_[sat_ ? 1 : band]), 5);
      a.insert(a.end(), bcd.begin(), bcd.end());
      end_.write(icom::frame(icom::kController, kAddr, 0x1C, a));
    } else if ((f->cmd == 0x16 && d.size() == 2 && d[0] == 0x5A) || (f->cmd == 0x1A && d.size() == 2 && d[0] == 0x07)) {
      if (sat_answer == SatAnswer::data) {
        end_.write(icom::frame(icom::kController, kAddr, f->cmd, Bytes{d[0], 0x00}));   // the value, not taken
      } else if (sat_answer == SatAnswer::fb) {
        if (!refuse_satmode) sat_ = d[1] == 0x01;
        answer(!refuse_satmode);
      }
    } else if (f->cmd == 0x1B && d.size() == 4 && d[0] == 0x00) {
      if (!refuse_tone) tone_ = static_cast<int>(*decode_bcd_big_endian(std::span(d).subspan(1)));
      answer(!refuse_tone);
    } else if (f->cmd == 0x16 && d.size() == 2 && d[0] == 0x42) {
      if (!refuse_tone) tone_on_ = d[1] == 0x01;
      answer(!refuse_tone);
    } else {
      answer(false);
    }
  }
  PtyEnd end_;
  const bool echo_;
  const std::uint8_t kAddr;
  std::atomic<bool> stop_{false};
  std::mutex mu_;
  std::vector<Bytes> frames_;
  Hz hz_[2] = {145'000'000, 435'000'000};
  bool selected_main_ = true;
  bool sat_ = false;
  bool off_ = false;
  int tone_ = 885;
  bool tone_on_ = false;
  std::thread thread_;
};

// A radio that takes commands and may answer: the pty, the thread reading it and the log of the
// commands it took (as text), shared by the FT-847/FT-817 and TS-2000 responders. A derived
// responder's take() cuts what came in into commands, records and answers them (mu_ held).
class CommandResponder {
 public:
  explicit CommandResponder(const std::string& path) : end_(path) {}
  virtual ~CommandResponder() = default;
  std::vector<std::string> commands() {
    std::lock_guard lock(mu_);
    return cmds_;
  }
  void clear() {
    std::lock_guard lock(mu_);
    cmds_.clear();
  }

 protected:
  void start() { thread_ = std::thread([this] { run(); }); }
  void stop() {
    stop_ = true;
    thread_.join();
  }
  virtual void take(const std::vector<std::uint8_t>& bytes) = 0;
  PtyEnd end_;
  std::mutex mu_;
  std::vector<std::string> cmds_;

 private:
  void run() {
    while (!stop_) {
      auto bytes = end_.read(64, 20ms);
      std::lock_guard lock(mu_);
      take(bytes);
    }
  }
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// An FT-847 (Hamlib ft847.c): 5-byte commands, nothing acknowledged; 03/13/23 answer 4 BCD bytes
// of 10 Hz and the mode. And an FT-817 (ft817.c): 01 / 07 / 03 on its one VFO.
class Yaesu5 final : public CommandResponder {
 public:
  explicit Yaesu5(const std::string& path) : CommandResponder(path) { start(); }
  ~Yaesu5() override { stop(); }
  void turn(std::uint8_t vfo_nibble, Hz delta) {
    std::lock_guard lock(mu_);
    hz_[vfo_nibble] += delta;
  }
  Hz frequency(std::uint8_t vfo_nibble) {
    std::lock_guard lock(mu_);
    return hz_[vfo_nibble];
  }
  // Switched off: takes and answers nothing; switched on again, an FT-847 takes nothing but CAT ON
  // (00 00 00 00 00) and is out of satellite mode.
  void power(bool on, bool needs_cat_on) {
    std::lock_guard lock(mu_);
    if (on && off_) cat_off_ = needs_cat_on, sat_ = false;
    off_ = !on;
    buf_.clear();
  }
  bool satellite() {
    std::lock_guard lock(mu_);
    return sat_;
  }

 private:
  void take(const std::vector<std::uint8_t>& bytes) override {
    if (off_) return;
    buf_.insert(buf_.end(), bytes.begin(), bytes.end());
    while (buf_.size() >= 5) {
      const Bytes c(buf_.begin(), buf_.begin() + 5);
      buf_.erase(buf_.begin(), buf_.begin() + 5);
      cmds_.push_back(to_hex(c));
      if (c == Bytes{0, 0, 0, 0, 0}) cat_off_ = false;
      if (cat_off_) continue;
      if (c == Bytes{0, 0, 0, 0, 0x4E}) sat_ = true;
      if (c == Bytes{0, 0, 0, 0, 0x8E}) sat_ = false;
      const std::uint8_t op = c[4] & 0x0F, vfo = c[4] & 0xF0;
      if (op == 0x01) hz_[vfo] = static_cast<Hz>(*decode_bcd_big_endian(std::span(c).first(4)) * 10);
      if (op == 0x03) {
        Bytes a = bcd_big_endian(static_cast<std::uint64_t>(hz_[vfo] / 10), 4);
        a.push_back(0x01);
        end_.write(a);
      }
    }
  }
  Bytes buf_;
  std::map<std::uint8_t, Hz> hz_;
  bool off_ = false, cat_off_ = false, sat_ = false;
};

// A TS-2000 as its sources describe it (docs/radio.md, "TS-2000 SA"): FA/FB set VFO A/B (11 digits
// of Hz; in satellite mode A is Main, the downlink, B is Sub, the uplink) and FA; / FB; answer them;
// SA; answers the seven digits and an 8-character name, SA<7 digits>; sets them, refused (?;) while
// VFO A is in memory mode (FR2); FR; is refused in satellite mode; MD, TN, TO go to the CTRL band
// (P4) in satellite mode, to the selected VFO (FR) outside it; TO; answers the encoder.
// `hamlib_sim` answers as Hamlib's simulators/simkenwood.c does: SA; with SA0;, every set of SA
// and TO; ignored.
class Ts2000 final : public CommandResponder {
 public:
  explicit Ts2000(const std::string& path, std::string sa = "0010000", char fr = '0') : CommandResponder(path), sa_(std::move(sa)), fr_(fr) {
    start();
  }
  ~Ts2000() override { stop(); }
  bool refuse_tone = false;
  bool hamlib_sim = false;
  void turn(char vfo, Hz delta) {
    std::lock_guard lock(mu_);
    hz_[vfo] += delta;
  }
  std::string sa() {
    std::lock_guard lock(mu_);
    return sa_;
  }
  // Switched off: takes and answers nothing; switched on again: out of satellite mode (SA P1 0).
  void power(bool on) {
    std::lock_guard lock(mu_);
    if (on && off_) sa_[0] = '0';
    off_ = !on;
    text_.clear();
  }
  Hz frequency(char vfo) {
    std::lock_guard lock(mu_);
    return hz_[vfo];
  }
  // A band's mode, tone and encoder ("MD4 TN01 TO1"): 'M' Main, 'S' Sub (satellite mode), or
  // '0' / '1' VFO A / B outside it.
  std::string band(char b) {
    std::lock_guard lock(mu_);
    return mode_[b] + " " + tone_[b] + " TO" + (on_[b] ? '1' : '0');
  }

 private:
  void answer(const std::string& a) { end_.write(std::vector<std::uint8_t>(a.begin(), a.end())); }
  char ctrl() const { return sa_[0] == '1' ? (sa_[3] == '1' ? 'S' : 'M') : fr_; }
  void take(const std::vector<std::uint8_t>& bytes) override {
    if (off_) return;
    text_.append(bytes.begin(), bytes.end());
    std::string rest;
    for (const std::string& c : kenwood::split_commands(text_, &rest)) {
      cmds_.push_back(c);
      if (auto f = kenwood::decode_frequency(c)) hz_[f->vfo == kenwood::Vfo::a ? 'A' : 'B'] = f->hz;
      if (c == "FA;" || c == "FB;")
        answer(kenwood::set_frequency(c[1] == 'A' ? kenwood::Vfo::a : kenwood::Vfo::b, hz_[c[1]]));
      if (c == "SA;") answer(hamlib_sim ? "SA0;" : "SA" + sa_ + "ISS     ;");
      if (c.size() == 10 && c.starts_with("SA") && !hamlib_sim) {
        if (fr_ == '2') answer("?;");
        else sa_ = c.substr(2, 7);
      }
      if (c == "FR;") answer(sa_[0] == '1' ? "?;" : std::string("FR") + fr_ + ";");
      if (c.size() == 4 && c.starts_with("FR")) fr_ = c[2];
      if (c.size() == 4 && c.starts_with("MD")) mode_[ctrl()] = c.substr(0, 3);
      if (c.size() == 5 && c.starts_with("TN")) {
        if (refuse_tone) answer("?;");
        else tone_[ctrl()] = c.substr(0, 4);
      }
      if (c == "TO0;" || c == "TO1;") on_[ctrl()] = c[2] == '1';
      if (c == "TO;" && !hamlib_sim) answer(on_[ctrl()] ? "TO1;" : "TO0;");
    }
    text_ = rest;
  }
  std::string text_;
  std::string sa_;
  char fr_;
  bool off_ = false;
  std::map<char, Hz> hz_;
  std::map<char, std::string> mode_, tone_;
  std::map<char, bool> on_;
};

// Two FT-817s, each on a pty pair of its own, as one station's radios: --radio ft817:... for the
// downlink, --uplink-radio ft818:... for the uplink (ok() false without socat).
struct Ft817Pair {
  PtyPair a, b;
  std::optional<Yaesu5> down, up;
  MakeRadio made;

  explicit Ft817Pair(const DriverTiming& timing) {
    if (!a.ok() || !b.ok()) return;
    down.emplace(a.test_side());
    up.emplace(b.test_side());
    const auto down_spec = parse_radio_spec("ft817:" + a.radio_side());
    const auto up_spec = parse_radio_spec("ft818:" + b.radio_side(), "--uplink-radio");
    made = make_radios(*down_spec.spec, *up_spec.spec, RadioConfig{}, timing);
  }
  bool ok() const { return made.driver != nullptr; }
  RadioDriver& radio() { return *made.driver; }
};

}  // namespace tbtest
