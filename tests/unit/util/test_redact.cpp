// Issue 33, defect 2: no credential reaches a log line, a reply or an error text, whatever the case
// or form. Exact expected texts for each form the attack used.
#include "util/redact.h"

#include <doctest/doctest.h>

using tb::redact::text;
using tb::redact::url_credentials;

TEST_CASE("URL credentials are redacted anywhere in a text, any scheme, any case") {
  CHECK(text("download failed: http://op:HttpPass77@127.0.0.1:1/x.txt") ==
        "download failed: http://op:<redacted>@127.0.0.1:1/x.txt");
  CHECK(text("HTTP://op:HttpPass77@127.0.0.1:1/x.txt: Couldn't connect") ==
        "HTTP://op:<redacted>@127.0.0.1:1/x.txt: Couldn't connect");
  CHECK(text("'SATELLITE_FTP?,ftp://u:PW@host,user' and sftp://a:b@c.example") ==
        "'SATELLITE_FTP?,ftp://u:<redacted>@host,user' and sftp://a:<redacted>@c.example");
  CHECK(url_credentials("https://user:p@ss:w0rd@host.example/path?q=1") == "https://user:<redacted>@host.example/path?q=1");
  CHECK(url_credentials("ftp://anonymous@host/x") == "ftp://anonymous@host/x");  // a user name alone
  CHECK(url_credentials("https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur") ==
        "https://celestrak.org/NORAD/elements/gp.php?GROUP=amateur");
  CHECK(url_credentials("no url here: a@b:c") == "no url here: a@b:c");
  CHECK(url_credentials("ftp://u:PW@h ftp://v:QQ@k") == "ftp://u:<redacted>@h ftp://v:<redacted>@k");
}

TEST_CASE("Password commands keep their verb and lose their secret") {
  CHECK(text("rotctld: client 127.0.0.1:5: '\\password RealSecret42' -> 'RPRT -11'") ==
        "rotctld: client 127.0.0.1:5: '\\password <redacted>' -> 'RPRT -11'");
  CHECK(text("'\\PASSWORD  Secret' -> 'RPRT 0'") == "'\\PASSWORD  <redacted>' -> 'RPRT 0'");
  CHECK(text("host: client x: 'PASS RealSecret42' -> 'ERROR'") == "host: client x: 'PASS <redacted>' -> 'ERROR'");
  CHECK(text("host: client x: 'pass Real Secret 42' -> 'ERROR'") == "host: client x: 'pass <redacted>' -> 'ERROR'");
  // Not a password command: left as it is.
  CHECK(text("PASS OUTSIDE LIMITS (antenna keeps to 0-180)") == "PASS OUTSIDE LIMITS (antenna keeps to 0-180)");
  CHECK(text("'PASSWORD'") == "'PASSWORD'");
  CHECK(text("'\\password'") == "'\\password'");
  CHECK(text("the next pass is at 12:00") == "the next pass is at 12:00");
}
