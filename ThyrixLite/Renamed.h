#pragma once
/// @file Renamed.h
/// @brief Names of the original Thyrix that are spelled differently here (and former names of
/// this one): code that uses them fails to compile with an error that names the new spelling.
///
/// Each old name is declared where the original had it, with one of these types, which are
/// declared and never defined (`<old>_is_now_<new>`). Overriding an old virtual function
/// conflicts with its return type; calling it, reading or assigning an old field uses an
/// incomplete type: the compiler refuses each and prints the type's name, so code written for
/// the original cannot compile into a method that is never called. docs/PortingFromThyrix.md
/// maps every name of the original users' guide to its name here.

namespace thyrix::renamed {

/// PhysicalObject::controll() is PhysicalObject::control().
struct controll_is_now_control;
/// An agent's nSensors is its sensorCount.
struct nSensors_is_now_sensorCount;
/// An agent's nEffectors is its effectorCount.
struct nEffectors_is_now_effectorCount;
/// ContactSolverSettings::baraffMaxContacts is ContactSolverSettings::baraffMaxIslandContacts.
struct baraffMaxContacts_is_now_baraffMaxIslandContacts;

}  // namespace thyrix::renamed
