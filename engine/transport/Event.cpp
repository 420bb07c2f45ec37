#include "transport/Event.hpp"

namespace dropscope {

std::string_view eventTypeName(EventType type) {
    switch (type) {
    case EventType::Emit: return "emit";
    case EventType::Reflect: return "reflect";
    case EventType::Refract: return "refract";
    case EventType::Tir: return "tir";
    case EventType::Absorb: return "absorb";
    case EventType::Escape: return "escape";
    case EventType::Lost: return "lost";
    case EventType::Detect: return "detect";
    case EventType::Truncated: return "truncated";
    case EventType::Diffract: return "diffract";
    }
    return "?";
}

std::string_view lostReasonName(LostReason reason) {
    switch (reason) {
    case LostReason::EventCap: return "event_cap";
    case LostReason::UndefinedNormal: return "undefined_normal";
    case LostReason::MediumMismatch: return "medium_mismatch";
    case LostReason::NoExit: return "no_exit";
    }
    return "?";
}

std::string_view lostReasonMeaning(LostReason reason) {
    switch (reason) {
    case LostReason::EventCap: return "after too many surface events (--max-events)";
    case LostReason::UndefinedNormal: return "at box edges or vertices, where a surface has no normal";
    case LostReason::MediumMismatch: return "at a surface that does not bound the photon's medium (touching shapes)";
    case LostReason::NoExit: return "inside a shape with no surface ahead (rounding)";
    }
    return "?";
}

}  // namespace dropscope
