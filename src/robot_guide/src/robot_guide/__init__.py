"""robot_guide: poses of the robots a camera sees, in the seeing robot's odometry frame, and
the ``guide(Name, Seconds)`` action that keeps one of them centred in the camera."""
