//! ParaView output (being written).
