// Fixture: cites eq. 9.1, Eqs. 7.1–7.3 and eqs. 8.1 and 8.2.
