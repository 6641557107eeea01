#include "server/listener.hpp"

#include <boost/asio/strand.hpp>
#include <cstdio>

namespace net = boost::asio;

namespace kontakt::server {

Listener::Listener(net::io_context& ioc, const net::ip::tcp::endpoint& endpoint, SessionContext& ctx)
    : ioc_(ioc), acceptor_(net::make_strand(ioc)), ctx_(ctx) {
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(net::socket_base::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen(net::socket_base::max_listen_connections);
}

void Listener::start() { do_accept(); }

void Listener::stop() {
  net::post(acceptor_.get_executor(), [self = shared_from_this()] {
    boost::system::error_code ec;
    self->acceptor_.close(ec);
  });
}

unsigned short Listener::port() const { return acceptor_.local_endpoint().port(); }

void Listener::do_accept() {
  acceptor_.async_accept(net::make_strand(ioc_), [self = shared_from_this()](
                                                     boost::system::error_code ec,
                                                     net::ip::tcp::socket socket) {
    if (ec == net::error::operation_aborted || !self->acceptor_.is_open()) return;
    if (ec) {
      std::fprintf(stderr, "kontaktd: accept: %s\n", ec.message().c_str());
    } else {
      std::make_shared<HttpSession>(std::move(socket), self->ctx_)->start();
    }
    self->do_accept();
  });
}

}  // namespace kontakt::server
