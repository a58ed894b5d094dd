% ccx_rounding_bound(PREFIX, N): first-order bound of what the rounding of
% K and M to the 14 significant digits ccx writes (%20.13e: a relative
% 5e-14 an entry) moves the N lowest eigenvalues, relative, the largest
% over the N: for an eigenpair (lambda, x) of K x = lambda M x and entry
% perturbations |dK| <= 5e-14 |K|, |dM| <= 5e-14 |M| (componentwise),
% |d lambda| <= 5e-14 (|x|'|K||x| + lambda |x|'|M||x|) / (x'Mx) to first
% order; modes zero within that bound (rigid-body modes) are left out. Reads PREFIX.sti and PREFIX.mas (upper triangle, as ccx writes
% them). Used offline (Octave) for the "rounding" column of
% verification/imports/ccx-corpus.tsv:
%   octave-cli --eval "ccx_rounding_bound('build/ccx-cache/deck-...-matrices/job', 10)"
function ccx_rounding_bound(prefix, nmodes)
  K = load([prefix '.sti']);
  M = load([prefix '.mas']);
  n = max(max(K(:, 1:2)));
  sym = @(A) A + A' - diag(diag(A));
  A = sym(sparse(K(:, 1), K(:, 2), K(:, 3), n, n));
  B = sym(sparse(M(:, 1), M(:, 2), M(:, 3), n, n));
  k = min(nmodes, n);
  if n <= 3000
    % The pencil (M, K + M): a singular M (massless dofs: mu = 0, no finite
    % eigenvalue) and a free part's singular K are both taken; lambda = 1/mu - 1.
    [V, D] = eig(full(B), full(A) + full(B));
    mu = diag(D);
    keep = mu > 1e-13 * max(mu);
    V = V(:, keep);
    D = diag(1 ./ mu(keep) - 1);
  else
    [V, D] = eigs(A, B, k, 1); % about 1, as ccx's shift
  end
  [d, order] = sort(diag(D));
  V = V(:, order);
  worst = 0;
  for j = 1:k
    x = V(:, j);
    bound = 5e-14 * (abs(x)' * abs(A) * abs(x) + abs(d(j)) * abs(x)' * abs(B) * abs(x)) / (x' * B * x);
    if bound < abs(d(j)) % a mode zero within its bound (rigid) has no relative bound
      worst = max(worst, bound / abs(d(j)));
    end
  end
  printf('%.2e\n', worst);
end
