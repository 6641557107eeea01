// The exact block headers CalculiX 2.20 writes to the .dat file, one table.
// Every string was established by running ccx 2.20 (/usr/bin/ccx) on small decks and on the
// examples of calculix-ccx-test; see proto/results_layout.md for the experiments.
// A header line is: header_prefix + SETNAME + " and time " + E14.7(total time); contact
// blocks name no set: header_prefix + E14.7(total time).
#pragma once

#include <string_view>

namespace kontakt::output {

enum class DatBlock {
  U,            ///< *NODE PRINT U
  RF,           ///< *NODE PRINT RF
  RF_TOTAL,     ///< RF with TOTALS=YES (after the node rows) or TOTALS=ONLY (alone)
  S,            ///< *EL PRINT S (integration points)
  E,            ///< *EL PRINT E
  ENER,         ///< *EL PRINT ENER (energy density per point; TOTALS has no effect)
  PEEQ,         ///< *EL PRINT PEEQ (no block at all for purely elastic models)
  ELSE,         ///< *EL PRINT ELSE (energy per element)
  ELSE_TOTAL,   ///< ELSE with TOTALS=YES/ONLY
  EVOL,         ///< *EL PRINT EVOL (volume per element)
  EVOL_TOTAL,   ///< EVOL with TOTALS=YES/ONLY
  CDIS_FACE,    ///< *CONTACT PRINT CDIS, surface-to-surface (rows per integration point)
  CSTR_FACE,    ///< CSTR, surface-to-surface
  CELS_FACE,    ///< CELS, surface-to-surface
  CDIS_NODE,    ///< CDIS, node-to-surface (rows per slave node)
  CSTR_NODE,    ///< CSTR, node-to-surface
  CELS_NODE,    ///< CELS, node-to-surface
  CELS_TOTAL,   ///< CELS with TOTALS=YES/ONLY
};

struct DatHeader {
  DatBlock block;
  std::string_view prefix;  ///< everything up to the set name, including the leading blank
};

/// Note the missing blank before "for set" in ccx's PEEQ header: that is what ccx prints.
inline constexpr DatHeader kDatHeaders[] = {
    {DatBlock::U, " displacements (vx,vy,vz) for set "},
    {DatBlock::RF, " forces (fx,fy,fz) for set "},
    {DatBlock::RF_TOTAL, " total force (fx,fy,fz) for set "},
    {DatBlock::S, " stresses (elem, integ.pnt.,sxx,syy,szz,sxy,sxz,syz) for set "},
    {DatBlock::E, " strains (elem, integ.pnt.,exx,eyy,ezz,exy,exz,eyz) for set "},
    {DatBlock::ENER, " internal energy density (elem, integ.pnt.,energy) for set "},
    {DatBlock::PEEQ, " equivalent plastic strain (elem, integ.pnt.,pe)for set "},
    {DatBlock::ELSE, " internal energy (element, energy) for set "},
    {DatBlock::ELSE_TOTAL, " total internal energy for set "},
    {DatBlock::EVOL, " volume (element, volume) for set "},
    {DatBlock::EVOL_TOTAL, " total volume for set "},
    // Contact blocks: the prefix runs up to the time. Note ccx's missing blanks in the CELS
    // headers ("energy)for", "forall") and the single blank before the time.
    {DatBlock::CDIS_FACE, " relative contact displacement (slave element+face,normal,tang1,tang2)"
                          " for all contact elements and time"},
    {DatBlock::CSTR_FACE, " contact stress (slave element+face,press,tang1,tang2) for all contact"
                          " elements and time"},
    {DatBlock::CELS_FACE, " contact print energy (slave element+face,energy)for all contact"
                          " elements and time"},
    {DatBlock::CDIS_NODE, " relative contact displacement (slave node,normal,tang1,tang2) for all"
                          " contact elements and time"},
    {DatBlock::CSTR_NODE, " contact stress (slave node,press,tang1,tang2) for all contact"
                          " elements and time"},
    {DatBlock::CELS_NODE, " contact print energy (slave node,energy) forall contact elements and"
                          " time"},
    {DatBlock::CELS_TOTAL, " total contact spring energy for time "},
};

constexpr std::string_view dat_header_prefix(DatBlock b) {
  for (const auto& h : kDatHeaders)
    if (h.block == b) return h.prefix;
  return {};
}

}  // namespace kontakt::output
