"""Forces and the flywheel: what the linkage's motion asks of the drive.

``dynamics`` the joint forces, crank torque and power at each crank angle; ``guide`` where
the ram bears on its guide; ``rotors`` the other rotating parts; ``flywheel`` the cycle's
torque, energy fluctuation and flywheel; ``polygons`` the velocity, acceleration and force
polygons of the graphical method.
"""
