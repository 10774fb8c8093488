// The radio registry: one table of every radio trakbox can drive, Hamlib-style. Each entry names
// the model (`ic9700`) or family (`icom`), the spec form `--radio` takes for it, its defaults (CI-V
// address, serial speed, which band carries which link in satellite mode), what it can do (one or
// two links, satellite mode, read-back, CTCSS, tuning step) and the factory that builds its driver.
// `--radio MODEL:DEVICE[:BAUD]`, `trakbox --radio list` and menu 6-7 all read this one table.
#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "radio/config.h"
#include "radio/driver.h"

namespace tb::radio {

struct RadioSpec;
struct DriverTiming;
struct MakeRadio;

// How the spec after "NAME:" reads.
enum class SpecForm {
  none,          // sim: nothing
  device,        // icom:DEVICE (the family forms; the speed comes from menu 6-7)
  device_baud,   // ic9700:DEVICE[:BAUD][:maindown|:mainup]
  hamlib,        // hamlib:MODEL:DEVICE[:BAUD][:split|:mainsub]
  rigctld,       // rigctld[:HOST[:PORT]][:split|:mainsub]
  receiver,      // gqrx[:HOST[:PORT]]: a receiver's rigctld-like server (the row's port by default)
  flex,          // flex[:HOST[:PORT]][:duplex]: the SmartSDR TCP API (the row's port by default)
};

// Which satellite-mode command a model has.
enum class SatCommand {
  none,
  icom_16_5a,    // IC-9700, IC-9100: 16 5A 01 / 00
  icom_1a_07,    // IC-910H: 1A 07 01 / 00 (Hamlib's ic910.c)
  ft847,         // 00 00 00 00 4E / 8E
  ft736,         // 00 00 00 00 0E / 8E
  kenwood_sa,    // TS-2000: SA, read, changed and put back (kenwood::Satellite)
};

// The protocol a model speaks (its driver).
enum class Protocol { simulated, icom, kenwood, ft736, ft847, ft817, newcat, cat, hamlib, rigctld, receiver, flex };

struct RadioCaps {
  int links = 1;                 // 2: one radio carries downlink and uplink
  bool satellite_mode = false;   // a satellite (full duplex) mode trakbox switches on
  bool reads = false;            // the dial can be read back (dial follow)
  bool ctcss = false;            // a CTCSS encoder on the uplink trakbox can set
  Hz step_hz = 10;               // the finest frequency step the CAT format carries
  // Icom: 1C 03 reads the transmit frequency in satellite mode without a band select (IC-9700).
  bool reads_tx_1c03 = false;
  // A receiver's recorder (--record): audio started and stopped with AOS / LOS; IQ where the
  // receiver has it (GQRX 2.17's U IQRECORD, found by the probe at connect); read back (`u RECORD`).
  bool records_audio = false;
  bool records_iq = false;
  bool reads_recorder = false;
};

// What a radio carries: both links (one radio), or one of two (--uplink-radio): a satellite rig
// that is one of two is driven as a plain single-link radio on its current band, no satellite mode.
enum class RadioRole { both, downlink, uplink };

// A stretch of the spectrum a radio tunes, [from, to] in Hz.
struct HzRange {
  Hz from = 0;
  Hz to = 0;
  bool contains(Hz hz) const { return hz >= from && hz <= to; }
};

struct RadioModel;
using RadioFactory = MakeRadio (*)(const RadioModel& model, const RadioSpec& spec, const RadioConfig& config,
                                   const DriverTiming& timing, RadioRole role);

struct RadioModel {
  std::string_view name;         // "ic9700": what --radio takes before the first ':'
  std::string_view label;        // "Icom IC-9700"
  SpecForm form = SpecForm::device;
  Protocol protocol = Protocol::simulated;
  std::uint8_t civ_address = 0;  // Icom: the radio's factory CI-V address
  int baud = 0;                  // the serial speed used unless the spec gives one (0: as configured)
  // Satellite mode, one radio for both links: the link the Main band (Icom) carries; the other
  // link is on Sub. IC-9700: Main receives (Hamlib's icom_get_split_vfos: RX Main, TX Sub);
  // IC-9100 / IC-910H / IC-821H: Main transmits. `:mainup` / `:maindown` in the spec override it.
  Link main_link = Link::uplink;
  SatCommand satmode = SatCommand::none;
  bool four_byte_frequency = false;   // IC-820H/821H
  // The bands the radio tunes (empty: any frequency its CAT format carries). A frequency outside
  // them is a band it lacks: learnt once (LinkError::Action::lacks, "no 70 cm"), never a fault.
  std::span<const HzRange> bands{};
  // IC-905: from here up (its 10 GHz band) frequencies are 6 BCD bytes, and the band is there only
  // with Icom's transverter, said with `:xvtr` in the spec. 0: no such band.
  Hz xvtr_from = 0;
  RadioCaps caps;
  int hamlib_model = 0;          // Hamlib's number for the same radio (Hamlib 4.5), 0: none
  int port = 0;                  // a network radio's TCP port unless the spec gives one
  bool one_client = false;       // a network radio that serves one client at a time
  std::string_view note;         // one line for --radio list
  RadioFactory make = nullptr;
};

// The whole table, in the order --radio list prints it.
std::span<const RadioModel> radio_models();
// The entry named so (exact, lower case as listed); nullptr when none.
const RadioModel* find_radio_model(std::string_view name);
// The model entry for a Hamlib rig model number (3081 -> ic9700), for the Hamlib path's satellite
// mode defaults (which band transmits); nullptr when the registry has no such model.
const RadioModel* find_radio_model_by_hamlib(int hamlib_model);
// The spec form as --radio list prints it: "ic9700:DEVICE[:BAUD]".
std::string spec_form(const RadioModel& m);
// `trakbox --radio list`: one line per entry, a header first.
std::string radio_list_text();
// "ic9700, ic9100, ..." (every name), for error messages and menu 6-7.
std::string radio_model_names();

}  // namespace tb::radio
