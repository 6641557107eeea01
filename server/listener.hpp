// The accept loop: one HttpSession per connection, each on its own strand.
#pragma once

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <memory>

#include "server/http_session.hpp"

namespace kontakt::server {

class Listener : public std::enable_shared_from_this<Listener> {
 public:
  /// Binds and listens; throws boost::system::system_error when the address is unusable.
  Listener(boost::asio::io_context& ioc, const boost::asio::ip::tcp::endpoint& endpoint,
           SessionContext& ctx);
  void start();
  /// Stops accepting; open connections carry on.
  void stop();
  /// The bound port (useful with port 0).
  unsigned short port() const;

 private:
  void do_accept();

  boost::asio::io_context& ioc_;
  boost::asio::ip::tcp::acceptor acceptor_;
  SessionContext& ctx_;
};

}  // namespace kontakt::server
