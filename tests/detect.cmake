tagmap_test(test_tag_decoder SOURCES unit/test_tag_decoder.cpp LIBS tagmap_detect)
tagmap_test(test_pipeline SOURCES unit/test_pipeline.cpp LIBS tagmap_detect tagmap_io)
tagmap_test(test_stages SOURCES unit/test_stages.cpp LIBS tagmap_detect opencv_imgproc)
