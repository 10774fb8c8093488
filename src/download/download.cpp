#include "download/download.h"

#include <curl/curl.h>

#include <memory>
#include <string_view>

#include "util/redact.h"
#include "util/text.h"

namespace tb::download {

namespace {

void global_init() {
  static std::once_flag once;
  std::call_once(once, [] { curl_global_init(CURL_GLOBAL_DEFAULT); });
}

struct Transfer {
  std::string body;
  std::string etag, last_modified;
  std::size_t max_bytes = 0;
  bool too_big = false;
  const std::function<bool()>* abort = nullptr;
};

std::size_t on_data(char* ptr, std::size_t size, std::size_t n, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const std::size_t bytes = size * n;
  if (t->body.size() + bytes > t->max_bytes) {
    t->too_big = true;
    return 0;  // makes libcurl fail the transfer with CURLE_WRITE_ERROR
  }
  t->body.append(ptr, bytes);
  return bytes;
}

// Response headers: the validators of the last response (a redirect's are forgotten at the next
// status line).
std::size_t on_header(char* ptr, std::size_t size, std::size_t n, void* user) {
  auto* t = static_cast<Transfer*>(user);
  const std::size_t bytes = size * n;
  const std::string_view line(ptr, bytes);
  if (line.starts_with("HTTP/")) {
    t->etag.clear();
    t->last_modified.clear();
  } else if (const auto colon = line.find(':'); colon != std::string_view::npos) {
    const std::string name = text::lower(text::trim(line.substr(0, colon)));
    const std::string value(text::trim(line.substr(colon + 1), " \t\r\n"));
    if (name == "etag") t->etag = value;
    else if (name == "last-modified") t->last_modified = value;
  }
  return bytes;
}

int on_progress(void* user, curl_off_t, curl_off_t, curl_off_t, curl_off_t) {
  auto* t = static_cast<Transfer*>(user);
  return (t->abort && *t->abort && (*t->abort)()) ? 1 : 0;
}

}  // namespace

DownloadResult download(const DownloadRequest& r, const std::function<bool()>& abort) {
  global_init();
  DownloadResult out;
  if (!r.method.empty() && r.method != "POST") {
    out.error = redact::url_credentials(r.url) + ": method '" + r.method.substr(0, 16) + "' is not GET or POST";
    return out;
  }
  std::unique_ptr<CURL, void (*)(CURL*)> curl(curl_easy_init(), curl_easy_cleanup);
  if (!curl) {
    out.error = "libcurl could not start a transfer";
    return out;
  }
  Transfer t;
  t.max_bytes = r.max_bytes;
  t.abort = &abort;
  char errbuf[CURL_ERROR_SIZE] = {0};
  CURL* c = curl.get();
  curl_easy_setopt(c, CURLOPT_URL, r.url.c_str());
  curl_easy_setopt(c, CURLOPT_PROTOCOLS_STR, r.allow_file ? "http,https,ftp,ftps,sftp,file" : "http,https,ftp,ftps,sftp");
  curl_easy_setopt(c, CURLOPT_REDIR_PROTOCOLS_STR, "http,https");
  const bool post = r.method == "POST";
  if (post) {
    curl_easy_setopt(c, CURLOPT_PROTOCOLS_STR, "http,https");
    curl_easy_setopt(c, CURLOPT_POST, 1L);
    curl_easy_setopt(c, CURLOPT_POSTFIELDS, r.body.data());
    curl_easy_setopt(c, CURLOPT_POSTFIELDSIZE_LARGE, static_cast<curl_off_t>(r.body.size()));
  }
  curl_easy_setopt(c, CURLOPT_FOLLOWLOCATION, post ? 0L : 1L);
  curl_easy_setopt(c, CURLOPT_MAXREDIRS, 5L);
  curl_easy_setopt(c, CURLOPT_NOSIGNAL, 1L);
  curl_easy_setopt(c, CURLOPT_FAILONERROR, r.http_errors_fail ? 1L : 0L);
  curl_easy_setopt(c, CURLOPT_CONNECTTIMEOUT_MS, static_cast<long>(r.connect_timeout.count()));
  curl_easy_setopt(c, CURLOPT_TIMEOUT_MS, static_cast<long>(r.total_timeout.count()));
  curl_easy_setopt(c, CURLOPT_MAXFILESIZE_LARGE, static_cast<curl_off_t>(r.max_bytes));
  curl_easy_setopt(c, CURLOPT_WRITEFUNCTION, on_data);
  curl_easy_setopt(c, CURLOPT_WRITEDATA, &t);
  curl_easy_setopt(c, CURLOPT_NOPROGRESS, 0L);
  curl_easy_setopt(c, CURLOPT_XFERINFOFUNCTION, on_progress);
  curl_easy_setopt(c, CURLOPT_XFERINFODATA, &t);
  curl_easy_setopt(c, CURLOPT_ERRORBUFFER, errbuf);
  curl_easy_setopt(c, CURLOPT_USERAGENT, r.user_agent.c_str());
  curl_easy_setopt(c, CURLOPT_HEADERFUNCTION, on_header);
  curl_easy_setopt(c, CURLOPT_HEADERDATA, &t);
  std::unique_ptr<curl_slist, void (*)(curl_slist*)> headers(nullptr, curl_slist_free_all);
  auto add_header = [&](const std::string& h) { headers.reset(curl_slist_append(headers.release(), h.c_str())); };
  if (!r.if_none_match.empty()) add_header("If-None-Match: " + r.if_none_match);
  if (!r.if_modified_since.empty()) add_header("If-Modified-Since: " + r.if_modified_since);
  if (post && !r.content_type.empty()) add_header("Content-Type: " + r.content_type);
  if (post) add_header("Expect:");  // no 100-continue round trip for a small body
  if (headers) curl_easy_setopt(c, CURLOPT_HTTPHEADER, headers.get());
  if (!r.user.empty()) {
    curl_easy_setopt(c, CURLOPT_USERNAME, r.user.c_str());
    curl_easy_setopt(c, CURLOPT_PASSWORD, r.password.c_str());
  }
  const CURLcode rc = curl_easy_perform(c);
  curl_easy_getinfo(c, CURLINFO_RESPONSE_CODE, &out.status);
  if (char* final_url = nullptr; curl_easy_getinfo(c, CURLINFO_EFFECTIVE_URL, &final_url) == CURLE_OK && final_url)
    out.final_url = final_url;
  if (rc == CURLE_OK) {
    out.ok = true;
    out.not_modified = out.status == 304;
    out.body = std::move(t.body);
    out.etag = std::move(t.etag);
    out.last_modified = std::move(t.last_modified);
    return out;
  }
  if (t.too_big || rc == CURLE_FILESIZE_EXCEEDED) {
    out.error = redact::url_credentials(r.url) + ": larger than " + std::to_string(r.max_bytes) + " bytes";
  } else if (rc == CURLE_ABORTED_BY_CALLBACK) {
    out.error = redact::url_credentials(r.url) + ": cancelled";
  } else {
    // libcurl's own text may quote the URL: no error text carries its credentials.
    out.error = redact::text(r.url + ": " + (errbuf[0] ? std::string(errbuf) : std::string(curl_easy_strerror(rc))));
  }
  return out;
}

Downloader::Downloader() : worker_([this] { run(); }) {}

Downloader::~Downloader() {
  {
    std::lock_guard lk(m_);
    quit_ = true;
    jobs_.clear();
  }
  cv_.notify_all();
  worker_.join();
}

void Downloader::submit(DownloadRequest request, Callback done) {
  {
    std::lock_guard lk(m_);
    jobs_.push_back(Job{std::move(request), std::move(done)});
  }
  cv_.notify_all();
}

std::size_t Downloader::busy() const {
  std::lock_guard lk(m_);
  return jobs_.size() + (running_job_ ? 1 : 0);
}

void Downloader::run() {
  for (;;) {
    Job job;
    {
      std::unique_lock lk(m_);
      cv_.wait(lk, [&] { return quit_ || !jobs_.empty(); });
      if (quit_) return;
      job = std::move(jobs_.front());
      jobs_.pop_front();
      running_job_ = true;
    }
    DownloadResult result = download(job.request, [this] {
      std::lock_guard lk(m_);
      return quit_;
    });
    bool quit;
    {
      std::lock_guard lk(m_);
      quit = quit_;
    }
    if (!quit && job.done) job.done(std::move(result));
    std::lock_guard lk(m_);
    running_job_ = false;
  }
}

}  // namespace tb::download
