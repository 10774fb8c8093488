// Element-set downloads over HTTP(S) and FTP(S)/SFTP with libcurl, on a worker thread of their own.
// The Satrak unit's SATELLITE_HTTP/SATELLITE_FTP and the scheduled element refresh
// (tracker/elements_refresh.h) use them; the logger's uploads (live/logger_upload.h) POST JSON.
// libcurl blocks, so no transfer ever runs on the event loop: submit() queues a job and returns at
// once; the worker runs the jobs one at a time and hands each result to the job's callback **on
// the worker thread** (the Satrak unit posts it to its io_context). The destructor aborts a
// transfer in progress (within about 100 ms) and joins the worker; callbacks of jobs still queued
// then are not called.
#pragma once
#include <chrono>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <functional>
#include <mutex>
#include <string>
#include <thread>

namespace tb::download {

struct DownloadRequest {
  std::string url;           // http://, https://, ftp://, ftps:// or sftp://
  std::string user;          // empty: none (anonymous FTP)
  std::string password;
  std::chrono::milliseconds connect_timeout{10000};
  std::chrono::milliseconds total_timeout{60000};
  std::size_t max_bytes = 1 << 20;  // element files are small; anything bigger is refused
  // HTTP conditional request: the validators of the last good answer ("" = none). A server that
  // has nothing newer answers 304, which is ok and not_modified.
  std::string if_none_match;       // the ETag, sent as If-None-Match
  std::string if_modified_since;   // the Last-Modified date, sent as If-Modified-Since
  std::string user_agent = "trakbox";
  bool allow_file = false;         // file:// too (the operator's own sources; never a Satrak client's)
  // A POST (HTTP(S) only): "POST" with its body and Content-Type; "" is a GET. The body may hold a
  // secret (the logger's key): it is never put in an error text. A POST follows no redirect (libcurl
  // would turn it into a GET without its body); a 3xx answer is then the result.
  std::string method;
  std::string body;
  std::string content_type;        // "application/json"
  // false: an HTTP error status (4xx, 5xx) is an answer (ok, with its status and body: an API's
  // refusal is read); true: it fails the transfer ("The requested URL returned error: 404").
  bool http_errors_fail = true;
};

struct DownloadResult {
  bool ok = false;
  bool not_modified = false; // HTTP 304 to a conditional request (ok, empty body)
  long status = 0;           // the last HTTP status (after redirects); 0 for other protocols / no answer
  std::string body;          // the file (when ok)
  std::string error;         // one line: what went wrong (when not ok)
  std::string etag;          // the validators of the answer, for the next conditional request
  std::string last_modified;
  std::string final_url;     // where the redirects ended
};

class Downloader {
 public:
  using Callback = std::function<void(DownloadResult)>;
  Downloader();
  ~Downloader();
  Downloader(const Downloader&) = delete;
  Downloader& operator=(const Downloader&) = delete;

  void submit(DownloadRequest request, Callback done);
  // Jobs queued or running.
  std::size_t busy() const;

 private:
  void run();
  struct Job {
    DownloadRequest request;
    Callback done;
  };
  mutable std::mutex m_;
  std::condition_variable cv_;
  std::deque<Job> jobs_;
  bool running_job_ = false;
  bool quit_ = false;
  std::thread worker_;
};

// The transfer itself (blocking; what the worker runs). `abort` is polled during the transfer.
DownloadResult download(const DownloadRequest& request, const std::function<bool()>& abort = {});

}  // namespace tb::download
