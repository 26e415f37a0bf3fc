common/CMakeFiles/giocal_common.dir/calibration/run_counter.cc.o: \
 /work/main/common/calibration/run_counter.cc /usr/include/stdc-predef.h \
 /work/main/common/calibration/run_counter.h
