#pragma once
// TCP keepalive for the servers' client connections: after 60 s without traffic the kernel sends 3
// probes 10 s apart, so a peer that vanished (power cut, cable pulled, a laptop closed) is closed
// within about 90 s instead of holding one of the server's connections for ever.
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <sys/socket.h>

namespace tb::inet {

inline void enable_keepalive(int fd) {
  const int on = 1, idle = 60, interval = 10, count = 3;
  ::setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof on);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPIDLE, &idle, sizeof idle);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPINTVL, &interval, sizeof interval);
  ::setsockopt(fd, IPPROTO_TCP, TCP_KEEPCNT, &count, sizeof count);
}

}  // namespace tb::inet
