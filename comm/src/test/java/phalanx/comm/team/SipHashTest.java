package phalanx.comm.team;

import org.junit.jupiter.api.Test;

import static org.junit.jupiter.api.Assertions.assertEquals;

class SipHashTest {
    // Key 00 01 .. 0f, message 00 01 .. (n-1): the reference vectors of the SipHash paper (appendix A
    // and the reference implementation's vectors.h), read as little-endian 64-bit words.
    private static final long K0 = 0x0706050403020100L, K1 = 0x0f0e0d0c0b0a0908L;

    private static long hashOfFirst(int n) {
        byte[] m = new byte[n];
        for (int i = 0; i < n; i++) m[i] = (byte) i;
        return SipHash.hash(K0, K1, m, n);
    }

    @Test
    void matchesThePapersTestVectors() {
        assertEquals(0x726fdb47dd0e0e31L, hashOfFirst(0));
        assertEquals(0x74f839c593dc67fdL, hashOfFirst(1));
        assertEquals(0xa129ca6149be45e5L, hashOfFirst(15)); // the worked example of the paper
    }
}
