# tagmap_io: format readers, the binary PCD writer, malformed inputs, simplemaps.
tagmap_test(test_io
  SOURCES unit/test_io_formats.cpp unit/test_io_malformed.cpp unit/test_io_simplemap.cpp unit/test_io_las.cpp
  LIBS tagmap_io mrpt::maps mrpt::obs mrpt::io mrpt::serialization)
