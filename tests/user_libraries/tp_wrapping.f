C     tp_wrapping.f -- test user library in Fortran 77 (GFOSUB,
C     Force_Vector_TwoBody), as gfortran builds it (entry gfosub_; the
C     utilities SYSFNC, AKISPL and ERRMES by their Fortran names, names
C     blank-padded to their length), written the way published
C     ligament-wrapping code is: a cable from marker I (on a body) to
C     marker J (on ground), its tension a curve of the model.
C
C     USER(i_marker, j_marker, spline_id, L0, mode)
C       d    = DX, DY, DZ (I, J, J),   v = VX, VY, VZ (I, J, J, J)
C       L    = sqrt(d . d),  e = d / L          (no guard against L = 0)
C       Ldot = v . e,  strain = (L - L0) / L0,  rate = Ldot / L0
C       x    = strain + TREL * rate             (TREL = 1 ms: the curve is
C              read at the strain the cable reaches a relaxation time on)
C       T    = AKISPL(x, 0, spline_id) + P0 * f**1.5,  f = max(0, 1 - t/TF)
C              (a pretension of P0 = 20 N released over TF = 0.25 s)
C       F    = -(T + C * Ldot) e,  C = 0.01 N s/mm;  torques 0
C     in J's axes (J on ground: the ground's axes). The same queries and the
C     same AKISPL call in the dependency pass, where the host answers zeros:
C     there L = 0, e = 0/0 = NaN, so x is NaN and AKISPL is called with a
C     NaN argument, as real code that never guards L does; its outputs are
C     then NaN (a solver discards them). A refused query, or an AKISPL
C     error at a real call, stops the run through ERRMES.
C
C     mode 0: correct wherever L > 0. Expected verdict: PASS (at most a
C       warning about the dependency pass's NaN).
C     mode 1: the clamp of f forgotten, f = 1 - t/TF: for TIME > 0.25 s
C       f < 0 and f**1.5 is NaN, so every output is NaN at the states the
C       model reaches. Expected verdict: FAIL (a non-finite output).
      SUBROUTINE GFOSUB(ID, TIME, PAR, NPAR, DFLAG, IFLAG, RESULT)
      INTEGER ID, NPAR
      DOUBLE PRECISION TIME, PAR(*), RESULT(6)
      LOGICAL DFLAG, IFLAG
      DOUBLE PRECISION TREL, P0, TF, C
      PARAMETER (TREL = 1.0D-3, P0 = 20.0D0, TF = 0.25D0, C = 1.0D-2)
      LOGICAL ERRFLG, BAD
      INTEGER IPAR(4), ISPL, MODE, K
      DOUBLE PRECISION D(3), V(3), E(3), L, L0, LDOT, STRAIN, RATE, X
      DOUBLE PRECISION F, T, ARRAY(3)
      CHARACTER*6 DNAM(3)
      CHARACTER*6 VNAM(3)
      DATA DNAM /'DX', 'DY', 'DZ'/
      DATA VNAM /'VX', 'VY', 'VZ'/
      DO 10 K = 1, 6
         RESULT(K) = 0.0D0
   10 CONTINUE
      IF (NPAR .LT. 5) THEN
         CALL ERRMES(.TRUE.,
     &      'USER(i_marker, j_marker, spline_id, L0, mode) expected',
     &      ID, 'STOP')
         RETURN
      END IF
      L0 = PAR(4)
      MODE = NINT(PAR(5))
      IF (.NOT. (L0 .GT. 0.0D0)) THEN
         CALL ERRMES(.TRUE., 'USER parameter 4 (L0) must be > 0',
     &      ID, 'STOP')
         RETURN
      END IF
      IF (MODE .NE. 0 .AND. MODE .NE. 1) THEN
         CALL ERRMES(.TRUE., 'USER parameter 5 (mode) must be 0 or 1',
     &      ID, 'STOP')
         RETURN
      END IF
      IPAR(1) = NINT(PAR(1))
      IPAR(2) = NINT(PAR(2))
      IPAR(3) = NINT(PAR(2))
      IPAR(4) = NINT(PAR(2))
      ISPL = NINT(PAR(3))
C     the measures: the same calls whatever IFLAG
      BAD = .FALSE.
      DO 20 K = 1, 3
         CALL SYSFNC(DNAM(K), IPAR, 3, D(K), ERRFLG)
         IF (ERRFLG) BAD = .TRUE.
         CALL SYSFNC(VNAM(K), IPAR, 4, V(K), ERRFLG)
         IF (ERRFLG) BAD = .TRUE.
   20 CONTINUE
      CALL ERRMES(BAD, 'the host refused DX..DZ or VX..VZ', ID, 'STOP')
      IF (BAD) RETURN
C     the cable's length and direction, as published code has them
      L = SQRT(D(1)**2 + D(2)**2 + D(3)**2)
      DO 30 K = 1, 3
         E(K) = D(K) / L
   30 CONTINUE
      LDOT = V(1)*E(1) + V(2)*E(2) + V(3)*E(3)
      STRAIN = (L - L0) / L0
      RATE = LDOT / L0
      X = STRAIN + TREL * RATE
C     tension against strain: the model's Reference_Spline
      ARRAY(1) = 0.0D0
      ARRAY(2) = 0.0D0
      ARRAY(3) = 0.0D0
      CALL AKISPL(X, 0.0D0, ISPL, 0, ARRAY, ERRFLG)
      IF (ERRFLG .AND. .NOT. IFLAG) THEN
         CALL ERRMES(.TRUE., 'AKISPL refused the tension curve', ID,
     &      'STOP')
         RETURN
      END IF
C     the pretension, released over TF
      IF (MODE .EQ. 0) THEN
         F = MAX(0.0D0, 1.0D0 - TIME / TF)
      ELSE
         F = 1.0D0 - TIME / TF
      END IF
      T = ARRAY(1) + P0 * F**1.5D0
      DO 40 K = 1, 3
         RESULT(K) = -(T + C * LDOT) * E(K)
   40 CONTINUE
      RETURN
      END
