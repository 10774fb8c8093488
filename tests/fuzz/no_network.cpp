// For the fuzz targets that run a Satrak unit: SATELLITE_HTTP= and SATELLITE_FTP= start downloads,
// and a fuzzer mutating "https://celestrak.org/..." must not reach the network. This definition of
// libcurl's transfer call takes the place of the shared library's (the executable's symbol wins),
// so every download fails at once, as with no network, and nothing leaves the machine.
#include <curl/curl.h>

extern "C" CURLcode curl_easy_perform(CURL*) { return CURLE_COULDNT_CONNECT; }
