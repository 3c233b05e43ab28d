#include "impact/chain/chain.hpp"

#include <sstream>
#include <stdexcept>
#include <string>

namespace impact {

namespace {

void require(bool ok, const char* name, double value, const char* range) {
  if (ok) return;
  std::ostringstream msg;
  msg.precision(17);
  msg << "chain: " << name << " = " << value << " is out of range: " << range;
  throw std::invalid_argument(msg.str());
}

}  // namespace

void check_chain(const Chain& chain) {
  require(std::isfinite(chain.m1) && chain.m1 > 0, "m1", chain.m1, "finite, > 0");
  require(std::isfinite(chain.m2) && chain.m2 > 0, "m2", chain.m2, "finite, > 0");
  require(std::isfinite(chain.k) && chain.k >= 0, "k", chain.k, "finite, >= 0");
  require(std::isfinite(chain.ell), "ell", chain.ell, "finite");
  require(std::isfinite(chain.g), "g", chain.g, "finite");
  require(std::isfinite(chain.phi), "phi", chain.phi, "finite");
  if (chain.cor) require(*chain.cor >= 0 && *chain.cor <= 1, "cor", *chain.cor, "[0, 1]");
}

void check_chain_state(const Chain& chain, const ChainState& s) {
  for (int i = 0; i < 2; ++i) {
    require(std::isfinite(s.q(i)), i == 0 ? "x1" : "x2", s.q(i), "finite");
    require(std::isfinite(s.v(i)), i == 0 ? "v1" : "v2", s.v(i), "finite");
  }
  require(s.q(0) >= chain.phi, "x1", s.q(0),
          ">= phi (the lower mass starts on or above the floor)");
}

std::string describe(const ChainState& s) {
  std::ostringstream text;
  text.precision(17);
  text << "x1 = " << s.q(0) << ", x2 = " << s.q(1) << ", v1 = " << s.v(0) << ", v2 = " << s.v(1);
  return text.str();
}

}  // namespace impact
