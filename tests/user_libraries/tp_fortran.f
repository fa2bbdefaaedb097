C     tp_fortran.f -- test user library in Fortran 77 (GFOSUB,
C     Force_Vector_TwoBody), as gfortran builds it: the entry is gfosub_,
C     the utilities SYSFNC, STEP, IMPACT, RCNVRT, ERRMES and USRMES are
C     called by their Fortran names, names blank-padded to their length.
C
C     USER(i_marker, j_marker): a spring-damper in x (1000 N/mm, 2 N s/mm)
C     faded in over 0.1 s by STEP, a stop below z = 0 by IMPACT, and a
C     torsion spring on AX, AY, AZ turned to cosines by RCNVRT (AXAYAZ).
C     Every read is the same in the dependency pass. A refused query is
C     reported through ERRMES. A correct verifier must PASS it.
      SUBROUTINE GFOSUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, RESULT)
      INTEGER ID, NPAR
      DOUBLE PRECISION TIME, PAR(*), RESULT(6)
      LOGICAL DFLAG, IFLAG
      LOGICAL ERRFLG
      INTEGER IPAR(4), ISTAT, I
      DOUBLE PRECISION DX, VX, DZ, VZ, RAMP, STOP(3), ANG(3), A(9)
      DO 10 I = 1, 6
         RESULT(I) = 0.0D0
   10 CONTINUE
      IF (NPAR .LT. 2) RETURN
      IPAR(1) = INT(PAR(1))
      IPAR(2) = INT(PAR(2))
      IPAR(3) = INT(PAR(2))
      IPAR(4) = INT(PAR(2))
      CALL SYSFNC('DX  ', IPAR, 3, DX, ERRFLG)
      CALL ERRMES(ERRFLG, 'the host refused DX', ID, 'STOP')
      CALL SYSFNC('DZ', IPAR, 3, DZ, ERRFLG)
      CALL SYSFNC('VX', IPAR, 4, VX, ERRFLG)
      CALL SYSFNC('VZ      ', IPAR, 4, VZ, ERRFLG)
      CALL SYSFNC('AX', IPAR, 2, ANG(1), ERRFLG)
      CALL SYSFNC('AY', IPAR, 2, ANG(2), ERRFLG)
      CALL SYSFNC('AZ', IPAR, 2, ANG(3), ERRFLG)
      CALL STEP(TIME, 0.0D0, 0.0D0, 0.1D0, 1.0D0, 0, RAMP, ERRFLG)
      RESULT(1) = -RAMP * (1000.0D0 * DX + 2.0D0 * VX)
      CALL IMPACT(DZ, VZ, 0.0D0, 2000.0D0, 1.5D0, 5.0D0, 0.2D0, 0,
     &            STOP, ERRFLG)
      RESULT(3) = STOP(1)
      CALL RCNVRT('AXAYAZ', ANG, 'COSINES', A, ISTAT)
      IF (ISTAT .NE. 0) THEN
         CALL USRMES(.TRUE., 'RCNVRT refused AXAYAZ', ID, 'WARN')
         RETURN
      END IF
      RESULT(4) = -250.0D0 * (A(6) - A(8))
      RESULT(5) = -250.0D0 * (A(7) - A(3))
      RESULT(6) = -250.0D0 * (A(2) - A(4))
      RETURN
      END
