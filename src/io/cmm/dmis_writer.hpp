#pragma once
// DMIS program text for a probe plan (DMIS 5.2 statements; docs/formats.md
// "DMIS program", docs/cmm.md for running it).
//
//   $$ comments: program, part, revision, date, point count, probe, assumptions
//   DMISMN/'name',05.2         FILNAM/'name',05.2       UNITS/MM,ANGDEC
//   PN(PART)=PARTID/'part'     (when the part is named)
//   PR(REV)=PARTRV/'rev'      (when a revision is stated)
//   PL(PROGRAM)=PLANID/'name'
//   PRCOMP/ON                  (the CMM compensates the probe radius)
//   S(PROBE)=SNSDEF/PROBE,INDEX,POL,0,0,0,0,-1,head_length,diameter   SNSLCT/S(PROBE)
//   FEDRAT/POSVEL,MMPS,v       FEDRAT/MESVEL,MMPS,v   (positioning, measuring speed)
//   SNSET/APPRCH,a  SNSET/RETRCT,r  SNSET/SEARCH,s
//   T(PROFILE)=TOL/PROFP,lower,upper          (with a tolerance)
//   DID(RESULTS)=DEVICE/STOR,'name.dmo'  OPEN/DID(RESULTS),FDATA,DMIS,OUTPUT
//   MODE/PROG,MAN
//   the part alignment when the program has one (docs/cmm.md "Part
//   alignment"): datum features, the manual pass (MODE/MAN, TEXT/MAN
//   prompts, MEAS without PTMEAS), D(MANUAL)=DATSET, D(MANUAL_CAD)=TRANS,
//   MODE/PROG,MAN, the programmed pass (MEAS with GOTO and PTMEAS), GOTOs up
//   and over to the tour, D(DATUMS)=DATSET, D(PART)=TRANS, OUTPUT of the
//   datums; or, for a free-form part, the manual points (MODE/MAN, a
//   prompt, MEAS, OUTPUT each) and MODE/PROG,MAN
//   per point, in execution order:
//     GOTO/x,y,z ...                       (probe-centre moves, the last = approach point)
//     F(id)=FEAT/POINT,CART,x,y,z,i,j,k    (nominal contact point, outward normal)
//     MEAS/POINT,F(id),1
//     PTMEAS/CART,x,y,z,i,j,k
//     ENDMES
//     OUTPUT/FA(ID)[,TA(PROFILE)]          (the measured point, and its deviation
//                                           against the zone, to the results file)
//   GOTO/... (up to the clearance plane)   CLOSE/DID(RESULTS)   ENDFIL
//
// Labels are upper case (dmis_label): the plan id P0001 is F(P0001), the
// probe Probe1 is S(PROBE1). The SNSDEF length is the head-to-ball length
// (head's centre of rotation to ball centre), as DMIS defines it for an
// indexable head; the date is given, never read from the clock.
//
// Lines end in CR LF (what CMM controllers on Windows expect; readers accept
// both). Deterministic: the same program gives the same bytes.
#include <string>

#include "io/cmm/probe_program.hpp"

namespace furrow {

// Throws InputError (check_program) for something DMIS cannot carry.
std::string dmis_program_text(const ProbeProgram& program);

}  // namespace furrow
