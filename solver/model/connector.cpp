#include "model/model.hpp"

namespace kontakt::model {

std::string_view connector_type_name(Connector::Kind kind) {
  switch (kind) {
    case Connector::Kind::Spring: return "SPRINGA";
    case Connector::Kind::Gap: return "GAPUNI";
    case Connector::Kind::Truss: return "T3D2";
  }
  return "";
}

}  // namespace kontakt::model
