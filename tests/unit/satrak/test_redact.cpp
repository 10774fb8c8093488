// Secrets never reach the log: what satrak::redact_payload and redact_url keep of an exchange.
#include <doctest/doctest.h>

#include "satrak/redact.h"

using tb::satrak::redact_payload;
using tb::satrak::redact_url;

TEST_CASE("URL credentials are redacted, the rest of the URL kept") {
  CHECK(redact_url("ftp://user:s3cret@10.0.1.2:21/amateur.tle") == "ftp://user:<redacted>@10.0.1.2:21/amateur.tle");
  CHECK(redact_url("https://a:b@celestrak.org/x?y=1") == "https://a:<redacted>@celestrak.org/x?y=1");
  CHECK(redact_url("https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=tle") ==
        "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur&FORMAT=tle");
  CHECK(redact_url("ftp://anonymous@host/f") == "ftp://anonymous@host/f");
  CHECK(redact_url("http://host/path@x:y") == "http://host/path@x:y");  // '@' after the authority
  CHECK(redact_url("p:a@ss") == "p:a@ss");                              // not a URL
}

TEST_CASE("The FTP password of SATELLITE_FTP= and of its reply is redacted") {
  CHECK(redact_payload("SATELLITE_FTP=, 10.0.1.2,username,password,22,1,1") ==
        "SATELLITE_FTP=, 10.0.1.2,username,<redacted>,22,1,1");
  CHECK(redact_payload("satellite_ftp=,h,u,p,21,f.tle,ISS,1,1") == "satellite_ftp=,h,u,<redacted>,21,f.tle,ISS,1,1");
  CHECK(redact_payload("SATELLITE_FTP?,h,u,?,21,f.tle,ISS,1,1") == "SATELLITE_FTP?,h,u,?,21,f.tle,ISS,1,1");
  CHECK(redact_payload("SATELLITE_FTP=,OK") == "SATELLITE_FTP=,OK");
  CHECK(redact_payload("SATELLITE_HTTP=,https://u:pw@host/iss.tle,ISS,1,1") ==
        "SATELLITE_HTTP=,https://u:<redacted>@host/iss.tle,ISS,1,1");
  CHECK(redact_payload("REDUCTION=,4000,4000") == "REDUCTION=,4000,4000");
  CHECK(redact_payload("") == "");
}
