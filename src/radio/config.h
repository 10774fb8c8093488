// Radio configuration: what each satellite's radio entry holds (menu 3-1 F1/F2 fields, the 3-3
// freq/mode file) and how the station's radios are wired (menu 6-7 radio CAT port, menu 6-8 mic
// click). Values only; nothing here talks to hardware. Frequencies are integer Hz everywhere.
#pragma once
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace tb::radio {

using Hz = std::int64_t;

// Radio modes (not satellite modes). The manual offers FM, LSB, USB and None; CW is there for
// Hamlib radios, host-mode commands and the later firmware's FREQ.DAT (the CAT encoders map it too).
enum class Mode { none, fm, lsb, usb, cw };

const char* to_string(Mode m);                      // "FM", "LSB", "USB", "CW", "None"
// Case-insensitive: "fm", "FM", "usb", "none", "cw" ...
std::optional<Mode> parse_mode(std::string_view text);

// How Doppler reaches the radio for one satellite (menu 3-1 "Doppler correct.").
enum class DopplerControl { cat, mic_click };
const char* to_string(DopplerControl d);            // "CAT", "Mic-click"

// The later firmware's FREQ.DAT `ir` / `kr` flag: for this satellite the two radios (Icom main/sub)
// or VFOs (Kenwood) swap their downlink/uplink roles: Tuner::update swaps the two links' commands
// when menu 6-7's rig is the family the flag names (an Icom for `ir`, a Kenwood for `kr`).
enum class ReverseAssignment { none, icom_main_sub, kenwood_vfo };
const char* to_string(ReverseAssignment r);         // "", "ir", "kr"

// At most this many uplinks in one FREQ.DAT record: the default and three alternatives.
inline constexpr int kMaxUplinkChannels = 4;

// The per-satellite radio entry (menu 3-1: F1, F1OFFSET, F2, F2OFFSET, modes, Doppler, LCD MA).
// A frequency of 0 means "not configured": no Doppler is computed and nothing is sent for that link
// (the manual: "If F1 and F2 are not configured, no doppler correction will be calculated").
// The offset is added to the RF frequency to give the frequency the radio is tuned to
// (a converter: 2400.730 MHz with offset -2256.000 MHz -> 144.730 MHz at the radio).
struct SatelliteRadio {
  Hz downlink_hz = 0;          // F1: RF downlink frequency at the satellite
  Hz downlink_offset_hz = 0;   // F1OFFSET
  Hz uplink_hz = 0;            // F2: RF uplink frequency at the satellite
  Hz uplink_offset_hz = 0;     // F2OFFSET
  Mode downlink_mode = Mode::none;
  Mode uplink_mode = Mode::none;
  DopplerControl doppler = DopplerControl::cat;
  bool lcd_ma_display = false;
  // The later firmware's FREQ.DAT: further uplink channels (RF Hz, same offset and mode as F2) the
  // operator may step through, after the default uplink_hz; at most kMaxUplinkChannels - 1.
  std::vector<Hz> alternate_uplinks_hz;
  ReverseAssignment reverse = ReverseAssignment::none;
  // A linear transponder's passbands at the satellite (RF Hz; freq/mode `down=LO-HI up=LO-HI`,
  // `inv=y|n`, the SatNOGS transmitter list's edges). All four 0: not a known linear transponder.
  // With them the Tuner keeps the two links on the same spot of the passband (dial follow).
  Hz downlink_low_hz = 0, downlink_high_hz = 0;
  Hz uplink_low_hz = 0, uplink_high_hz = 0;
  bool inverting = false;
  // CTCSS tone for the uplink (FM satellites, freq/mode `tone=67.0`), in tenths of Hz; 0: none.
  int ctcss_tenths_hz = 0;

  bool has_downlink() const { return downlink_hz > 0; }
  bool has_passbands() const {
    return downlink_low_hz > 0 && downlink_high_hz >= downlink_low_hz && uplink_low_hz > 0 &&
           uplink_high_hz >= uplink_low_hz;
  }
  bool has_uplink() const { return uplink_hz > 0; }
  // Steps to the next uplink channel: uplink_hz becomes the first alternative and goes to the end
  // of the list, so repeated steps go round all of them. False (nothing changed) without any.
  bool next_uplink();
  bool operator==(const SatelliteRadio&) const = default;
};

// A named way of working a satellite (issue 59): RS-44 in "SSB", "CW" and "FT4", the ISS on its "FM"
// repeater, "APRS" and "SSTV", AO-07 in "Mode-B" and "Mode-A". Each mode is a whole radio entry:
// its downlink and uplink (or a transponder's passbands with the mode's spot inside them as F1/F2),
// the modes on each link, NOR/REV (`inverting`), the CTCSS tone; and the tone that arms the
// repeater before the operating tone (SO-50's 74.4 Hz), stored and shown, sent by the operator.
// The operator's remembered corrections are kept per satellite and mode name
// (RadioConfig::corrections, "RS-44 FT4").
// Where one field of a mode came from (issue 59's imports, store/mode_import.h): the source that
// gave it ("freqmode", "satnogs", "gpredict", "satpc32", "oscarwatch") and the value it gave, as
// store::field_value writes it. A field whose value is no longer that one was edited by the operator
// since. `offer_from`/`offer_value`: a list's value that differed and was not taken (a conflict),
// kept for `trakbox radio diff`; empty when none.
struct FieldSource {
  std::string from;
  std::string value;
  std::string offer_from;
  std::string offer_value;
  bool operator==(const FieldSource&) const = default;
};

struct SatelliteMode {
  std::string name;            // 1 to kMaxModeName characters: letters, digits, - + / . _
  SatelliteRadio radio;
  int arm_tone_tenths_hz = 0;  // 0: none
  // Field name ("downlink", "uplink", "downlink_mode", "uplink_mode", "passbands", "inverting",
  // "tone", "arm") -> its source; a field not here is the operator's (or empty).
  std::map<std::string, FieldSource> sources;
  bool operator==(const SatelliteMode&) const = default;
};
inline constexpr std::size_t kMaxModes = 16;
inline constexpr std::size_t kMaxModeName = 16;
// Whether text is a mode name as above; "" when it is, else what is wrong with it.
std::string mode_name_problem(std::string_view name);
// The name of the one mode a record made before modes existed becomes: "SSB" for a USB or LSB
// downlink, "FM", "CW", and "default" for a record without a downlink mode.
std::string default_mode_name(const SatelliteRadio& r);

// Menu 6-7.
enum class Rig { none, kenwood, yaesu, icom };
const char* to_string(Rig r);                       // "NONE", "KENWOOD", "YAESU", "ICOM"

// The radio model within a rig family, as the later firmware's STATION.DAT line 4 names it
// (KENWOOD711, YAESU_847, YAESU_736, YAESU_o ...). Stored and shown; the CAT drivers speak the
// family's protocol for every model.
enum class RigModel { generic, kenwood_711, yaesu_other, yaesu_847, yaesu_736 };
const char* to_string(RigModel m);                  // "", "TS-711", "other", "FT-847", "FT-736"

// The speed TrakBox's CAT port runs at for a rig unless told otherwise: Icom CI-V 1200, Kenwood and
// Yaesu 4800 (0 for none). effective_cat_baud: the configured speed, or else the standard one.
int standard_cat_baud(Rig r);
struct RadioConfig;
int effective_cat_baud(const RadioConfig& c);

// What the receiver trakbox drives records through a pass (--record, radio.record; docs/radio.md
// "Recording a pass"): nothing, its audio recorder (GQRX's and SDR++'s AOS/LOS), or its IQ recorder
// (GQRX's U IQRECORD).
enum class Record { off, audio, iq };
const char* to_string(Record r);                    // "off", "audio", "iq"

// Downlink correction Y / N / R. Reverse is for a down-converter with a high-side local
// oscillator: the Doppler correction is applied in the opposite direction at the radio.
enum class DownlinkCorrection { off, on, reverse };
// CAT commands for the Full orbit, or only while the satellite is at AOS (elevation >= -2.0 deg).
enum class CatPolicy { full_orbit, aos_only };
enum class PulsePolarity { normal, reverse };

// How an Icom single dual-band radio (IC-820H/821H/910) is addressed when the RX and TX addresses
// are the same: with main_tx_sub_rx each frequency is preceded by a band select (07 D0 main for
// the uplink, 07 D1 sub for the downlink), as these radios do in satellite mode.
enum class IcomBandSelect { none, main_tx_sub_rx };

// Menu 6-8. Factory values: the manual's 6-8 example shows the stored values before the operator
// types new ones (centre 550, reference 560) and 6-0 shows "Frequency step 100 Hz"; the three
// Y/N/N questions take the answers of the 6-8 example.
struct MicClickConfig {
  int centre_adc = 550;        // "Modem locked center ADC value" (ADC3, 0..1023)
  int reference_adc = 560;     // "Reference ADC value": |reference - centre| is the dead span
  Hz step_hz = 100;            // "Step Frequency": what one UP/DOWN pulse moves the radio
  bool cat_at_aos = true;      // "Frequency set CAT command at AOS"
  bool auto_up_at_aos = true;  // "Automatic up pulse generation at AOS"
  PulsePolarity polarity = PulsePolarity::normal;
  // STATION.DAT line 5 of the later firmware, "PARK[m][n]": the mic-click pulse width (m) and
  // interval (n) digits, 0 to 9; -1 when not given. Stored as written; their timing is not used.
  int park_pulse_width_digit = -1;
  int park_pulse_interval_digit = -1;

  int span() const { return reference_adc > centre_adc ? reference_adc - centre_adc
                                                       : centre_adc - reference_adc; }
  bool operator==(const MicClickConfig&) const = default;
};

// The later firmware's STATION.DAT line 6: after LOS the radios are tuned to these frequencies
// (radio frequencies: no converter offset) and modes, until the next AOS (Tuner::update).
struct RadioParking {
  bool enabled = false;
  Hz rx_hz = 0;
  Hz tx_hz = 0;
  Mode rx_mode = Mode::none;
  Mode tx_mode = Mode::none;
  bool operator==(const RadioParking&) const = default;
};

// Menu 6-7 and 6-8 together. Factory values: no CAT rig (trakbox's simulated radio answers),
// Icom addresses 00 (the manual: "The TrakBox default address is 00 which is a broadcast
// address"), uplink and downlink correction on and AOS-only CAT (the 6-7 example's answers, and
// 6-0 shows "CAT Rig KENWOOD AOS"), FT-736 standard FM filter.
struct RadioConfig {
  Rig rig = Rig::none;
  std::uint8_t icom_rx_address = 0x00;   // downlink radio
  std::uint8_t icom_tx_address = 0x00;   // uplink radio
  IcomBandSelect icom_band_select = IcomBandSelect::none;
  bool icom_four_byte_frequency = false; // IC-820H/821H: 4 BCD bytes, no 100 MHz / 1 GHz digits
  bool uplink_correction = true;
  DownlinkCorrection downlink_correction = DownlinkCorrection::on;
  CatPolicy cat_policy = CatPolicy::aos_only;
  bool ft736_wide_fm = false;            // FM filter changed for a wider one (UO-22); YAESUw847 too
  RigModel rig_model = RigModel::generic;
  // The native CAT port's speed (STATION.DAT line 4): 1200, 2400, 4800, 9600 or 19200, or 0 for the
  // rig's standard speed (standard_cat_baud).
  int cat_baud = 0;
  MicClickConfig mic_click;
  RadioParking parking;
  // Dial follow on linear transponders (menu 6-7 and the realtime display's D key): the radio's
  // frequency is read back each tick and a turn of the dial moves the spot instead of being undone.
  bool dial_follow = true;
  // The radio that carries the uplink when it is not the --radio one (--uplink-radio, menu 6-7):
  // a radio spec as --radio takes (radio/factory.h); empty: the one radio carries both links.
  std::string uplink_radio;
  // Operating practice (the 6-7 P question, --dial-rest, --doppler-step). A turn of one link's dial
  // moves the other link once the knob has rested this long (no further turn read back).
  int dial_rest_ms = 1000;
  // Doppler updates go to the radio when a link's frequency moved at least this far from the last
  // one sent: SSB/CW (and a link without a mode) tens of Hz, FM hundreds (FM radios tune coarsely
  // and the FM passband is wide, so an FM pass need not flood the CAT line).
  Hz doppler_step_ssb_hz = 20;
  Hz doppler_step_fm_hz = 100;
  // Corrections the operator found (realtime + / -) per satellite and downlink mode, "SO-50 FM" ->
  // Hz; applied when that satellite is next selected, forgotten with 0.
  std::map<std::string, Hz> corrections;
  // The uplink's (TX) corrections, the same way: "RS-44 USB" -> Hz added to the uplink radio's
  // frequency (the page's and host mode's TX offset), applied when that satellite is next selected.
  std::map<std::string, Hz> tx_corrections;
  // Recording (--record, --record-satellites): the receiver's recorder is started at AOS (the rotor
  // start elevation) of the satellite it is tuned to and stopped at LOS. record_satellites names
  // the satellites recorded, comma-separated ("": every satellite).
  Record record = Record::off;
  std::string record_satellites;

  bool operator==(const RadioConfig&) const = default;
};

// The radio's tuning resolution: every frequency sent is rounded to this (10 Hz for the
// Icom, Kenwood and Yaesu radios TrakBox drives; host-mode FU/FD are "to 10 Hz" as well).
inline constexpr Hz kTuningStepHz = 10;

}  // namespace tb::radio
