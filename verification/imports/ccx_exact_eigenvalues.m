% ccx_exact_eigenvalues(PREFIX, N, SIGMA): the N lowest eigenvalues of the
% matrices ccx stored (PREFIX.sti, PREFIX.mas: upper triangles, as ccx
% writes them), by a dense solve of the pencil (M, K - SIGMA M), SIGMA
% below the spectrum (K - SIGMA M positive definite), lambda = SIGMA + 1/mu;
% mu at most 1e-13 mu_max is a massless direction (no finite eigenvalue).
% Printed as an `exact` row's fragment of verification/imports/ccx-corpus.tsv,
% "n=DOFS LAMBDA_1 ... LAMBDA_N" (13 digits): the reference for a deck on
% which ccx's own Lanczos (ARPACK, shift 1, tol 1e-2) misses an eigenvalue
% or returns one the stored matrices do not have. Used offline (Octave):
%   octave-cli --eval "ccx_exact_eigenvalues('build/ccx-cache/deck-...-matrices/job', 10, -1)"
function ccx_exact_eigenvalues(prefix, nmodes, sigma)
  K = load([prefix '.sti']);
  M = load([prefix '.mas']);
  n = max(max(K(:, 1:2)));
  sym = @(A) A + A' - diag(diag(A));
  A = full(sym(sparse(K(:, 1), K(:, 2), K(:, 3), n, n)));
  B = full(sym(sparse(M(:, 1), M(:, 2), M(:, 3), n, n)));
  mu = eig(B, A - sigma * B);
  mu = mu(mu > 1e-13 * max(mu));
  lambda = sort(sigma + 1 ./ mu);
  printf('n=%d', n);
  printf(' %.12e', lambda(1:nmodes));
  printf('\n');
end
