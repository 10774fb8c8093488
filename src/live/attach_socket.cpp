// The attach socket's file (attach_internal.h): looked at before it is replaced, made with its mode
// from the start, removed only when it is still the one made (issue 38).
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <boost/asio/local/stream_protocol.hpp>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "live/attach_internal.h"

namespace tb::app {

namespace {

std::string file_kind(mode_t m) {
  if (S_ISLNK(m)) return "a symbolic link";
  if (S_ISDIR(m)) return "a folder";
  if (S_ISREG(m)) return "a file";
  if (S_ISFIFO(m)) return "a FIFO";
  return "a device or other special file";
}

}  // namespace

SocketId bind_socket(boost::asio::local::stream_protocol::acceptor& acceptor, const std::string& path) {
  using stream = boost::asio::local::stream_protocol;
  // What is at the path is looked at, not followed (lstat): only a socket is ever replaced, and only
  // one no process answers on -- left by a trakbox that did not end cleanly (the state lock says none
  // runs). A file, a folder or a link there is someone's: refused, untouched (issue 38).
  struct stat st{};
  if (::lstat(path.c_str(), &st) == 0) {
    if (!S_ISSOCK(st.st_mode))
      throw std::runtime_error(path + ": exists and is not a socket (" + file_kind(st.st_mode) +
                               "): left as it is; remove it or choose another --socket");
    stream::socket probe(acceptor.get_executor());
    boost::system::error_code ec;
    probe.connect(stream::endpoint(path), ec);
    if (!ec) throw std::runtime_error(path + ": a running trakbox answers there");
    if (::unlink(path.c_str()) != 0 && errno != ENOENT)
      throw std::runtime_error(path + ": a stale socket that cannot be removed: " + std::strerror(errno));
  }
  // Made for the owner and the group alone from the start by the umask at bind (0777 & ~0117 = 0660):
  // there is no moment when others may open it, and no chmod by name afterwards that a link swapped
  // in could redirect. lstat then checks that what is at the path is the socket made so.
  const mode_t old_mask = ::umask(0117);
  boost::system::error_code ec;
  acceptor.open(stream(), ec);
  if (!ec) acceptor.bind(stream::endpoint(path), ec);
  ::umask(old_mask);
  if (!ec) acceptor.listen(16, ec);
  if (ec) throw std::runtime_error(path + ": " + ec.message());
  if (::lstat(path.c_str(), &st) != 0 || !S_ISSOCK(st.st_mode))
    throw std::runtime_error(path + ": not the socket just made");
  // A default ACL on the folder overrides the umask: then the mode is set, on the socket itself (a
  // link is not followed: AT_SYMLINK_NOFOLLOW).
  if ((st.st_mode & 0777) != 0660 && ::fchmodat(AT_FDCWD, path.c_str(), 0660, AT_SYMLINK_NOFOLLOW) != 0)
    throw std::runtime_error(path + ": cannot make the socket 0660: " + std::strerror(errno));
  return {st.st_dev, st.st_ino};
}

void remove_socket(const std::string& path, SocketId made) {
  struct stat st{};
  if (::lstat(path.c_str(), &st) == 0 && S_ISSOCK(st.st_mode) && SocketId{st.st_dev, st.st_ino} == made)
    ::unlink(path.c_str());
}

}  // namespace tb::app
