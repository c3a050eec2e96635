"""pac-test: runs the ST tests of a PA-CONTROL machine program against the simulated PA-CONTROL (docs/user_tests.md)."""
