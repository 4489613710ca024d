// A student's specular.glsl in Moodle's download; the test refuses the format before grading it.
