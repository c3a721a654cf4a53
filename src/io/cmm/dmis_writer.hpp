#pragma once
// DMIS program text for a probe plan (DMIS 5.2 statements; docs/formats.md
// "DMIS program", docs/cmm.md for running it).
//
//   $$ comments: part, point count, probe, assumptions
//   DMISMN/'name',05.2         FILNAM/'name',05.2       UNITS/MM,ANGDEC
//   PRCOMP/ON                  (the CMM compensates the probe radius)
//   S(probe)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,length,diameter   SNSLCT/S(probe)
//   SNSET/APPRCH,a  SNSET/RETRCT,r  SNSET/SEARCH,s
//   DID(RESULTS)=DEVICE/STOR,'name.dmo'  OPEN/DID(RESULTS),FDATA,DMIS,OUTPUT
//   MODE/PROG,MAN
//   per point, in execution order:
//     GOTO/x,y,z ...                       (probe-centre moves, the last = approach point)
//     F(id)=FEAT/POINT,CART,x,y,z,i,j,k    (nominal contact point, outward normal)
//     MEAS/POINT,F(id),1
//     PTMEAS/CART,x,y,z,i,j,k
//     ENDMES
//     OUTPUT/FA(id)                        (the measured point to the results file)
//   GOTO/... (up to the clearance plane)   CLOSE/DID(RESULTS)   ENDFIL
//
// Lines end in CR LF (what CMM controllers on Windows expect; readers accept
// both). Deterministic: the same program gives the same bytes.
#include <string>

#include "io/cmm/probe_program.hpp"

namespace furrow {

// Throws InputError (check_program) for something DMIS cannot carry.
std::string dmis_program_text(const ProbeProgram& program);

}  // namespace furrow
