// What a hostile study hands gmsh: SystemCall runs a shell command.
SystemCall "touch sandbox_gmsh_geo_pwned";
Point(1) = {0, 0, 0, 1};
