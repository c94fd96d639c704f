//! Special functions the contact kernel needs: the exponential integrals E1 and Ei in scaled forms
//! (eˣE1(x), e⁻ˣEi(x)), accurate to a few ulp over the whole double range (MATH.md §2).
//! Owned by the foundation contact issue.
