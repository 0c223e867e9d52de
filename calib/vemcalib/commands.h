// vemcalib's subcommands; each add*Command registers one on the app and sets exitCode when it runs.
// Every command that writes a calibration writes it only when the whole calibration succeeded, and
// merges it into an existing camera file (the other sections are kept).
#pragma once

#include <CLI/CLI.hpp>

namespace vem::calibtool {

void addPhotometricCommand(CLI::App& app, int& exitCode);  // photometric_command.cpp
void addFisheyeCommand(CLI::App& app, int& exitCode);      // fisheye_command.cpp
void addResponseCommand(CLI::App& app, int& exitCode);     // response_command.cpp
void addSimulateCommand(CLI::App& app, int& exitCode);     // simulate_command.cpp
void addApplyCommand(CLI::App& app, int& exitCode);        // apply_command.cpp
void addShowCommand(CLI::App& app, int& exitCode);         // show_command.cpp
void addPlateCommand(CLI::App& app, int& exitCode);        // plate_command.cpp

// `vemcalib plate ...` (plate_command.cpp) gathers these: the scene ("plate") camera's calibration
// into a plate-camera file (calib/io/plate_camera_file.h), one section each.
void addPlateIntrinsicsCommand(CLI::App& plate, int& exitCode);  // plate_intrinsics_command.cpp
void addPlatePoseCommand(CLI::App& plate, int& exitCode);        // plate_pose_command.cpp
void addPlateProbeYawCommand(CLI::App& plate, int& exitCode);    // plate_probe_yaw_command.cpp
void addPlateColourCommand(CLI::App& plate, int& exitCode);      // plate_colour_command.cpp

// `vemcalib simulate ...` (simulate_command.cpp) gathers these, each registering one subcommand of
// `simulate`: calibration frames and raw frames from a known ("truth") camera file.
void addSimulatePatchesCommand(CLI::App& simulate, int& exitCode);   // simulate_command.cpp
void addSimulateFrameCommand(CLI::App& simulate, int& exitCode);     // simulate_command.cpp
void addSimulateBoardsCommand(CLI::App& simulate, int& exitCode);    // simulate_boards_command.cpp
void addSimulateBracketsCommand(CLI::App& simulate, int& exitCode);  // simulate_brackets_command.cpp
void addSimulatePlateCommand(CLI::App& simulate, int& exitCode);     // simulate_plate_command.cpp

}  // namespace vem::calibtool
