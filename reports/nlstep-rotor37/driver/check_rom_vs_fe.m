%========================================================================
% check_rom_vs_fe.m -- sanity check (written for rsi, not NLstep code):
% builds the FE model and the MacNeal ROM exactly as NLstep's example does
% (50 modes, 16 contact nodes) and compares, for unit forces at the 48
% contact dofs (global axes), the response at node 1353 dir 2 and at the
% contact dofs: (a) static (MCN is statically exact), (b) harmonic at
% 200 Hz and 600 Hz (undamped; approximate because of modal truncation).
% Usage: octave-cli -q --eval "NLSTEP_ROOT='...'; run('check_rom_vs_fe.m')"
%========================================================================
if ~exist('NLSTEP_ROOT','var'), NLSTEP_ROOT = getenv('NLSTEP_ROOT'); end
if isempty(NLSTEP_ROOT), error('set NLSTEP_ROOT (the prepared NLstep tree)'); end
ex = fullfile(NLSTEP_ROOT,'EXAMPLES','03_bladeCasingRubbing');
addpath(genpath(fullfile(NLSTEP_ROOT,'SRC')));
fe = FEmodel(fullfile(ex,'FEmodel','blade'));
nodeSet_contact = [188,190,192,194,196,198,200,203,253,255,257,259,261,263,265,267];
IB = getIndex2NodalDOF(fe,nodeSet_contact);
isens = getIndex2NodalDOF(fe,1353,2);
rom = CMS_ROM(fe,IB,50,'MCN');
nb = numel(IB); n = fe.n;
F = sparse(IB,1:nb,1,n,nb);
rows = [isens; IB(:)];
for fHz = [0 200 600]
    w2 = (2*pi*fHz)^2;
    Ufe = (fe.K - w2*fe.M)\F;
    % ROM: generalized forces T'*F; solve (Kr - w2 Mr) q = T'F; u = T q
    Ur = rom.T(rows,:)*((rom.K - w2*rom.M)\(rom.T'*F));
    err = max(max(abs(Ur - Ufe(rows,:))))/max(max(abs(Ufe(rows,:))));
    fprintf('f = %5.0f Hz: max rel. diff ROM vs FE (rows: dof 1353y + 48 contact dofs) = %.3e; u_1353y/F(188x)=%.6e FE, %.6e ROM\n', ...
        fHz, err, full(Ufe(isens,1)), Ur(1,1));
end
