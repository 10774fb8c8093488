// The event loop and the logger, declared: what runs on the station's loop and logs takes both by
// reference, and its header stays free of Asio and spdlog (as <iosfwd> is for streams).
#pragma once

namespace boost::asio {
class io_context;
}
namespace spdlog {
class logger;
}
