%========================================================================
% run_rotor37_plausible.m  --  Octave driver (written for the rsi project,
% not part of NLstep/NLvib).
%
% Runs NLstep's own example EXAMPLES/03_bladeCasingRubbing/
% bladeCasingRubbing.m (CONFIG = 'PLAUSIBLE', unchanged) under GNU Octave,
% then re-runs only the time integration (same inputs, tic/toc around the
% call) to get the contact states and solver info that the example script
% discards, and exports the results as CSV files.
%
% Usage (see setup_and_run.sh, which prepares the tree first):
%   OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 octave-cli -q \
%       --eval "NLSTEP_ROOT='WORK_DIR/NLstep'; OUT_DIR='WORK_DIR/out'; \
%               run('DRIVER_DIR/run_rotor37_plausible.m')"
% NLSTEP_ROOT may also come from the environment variable of that name;
% OUT_DIR defaults to ./out (relative to the directory Octave starts in).
%
% Requirements: NLSTEP_ROOT/SRC contains NLstep's SRC plus NLvib's SRC
% (with the CMS_ROM eigs-ordering fix), and the example's FEmodel folder
% contains blade.sti/blade.mas/blade.dof written by CalculiX (ccx -i blade).
%========================================================================
global DRV
if ~exist('NLSTEP_ROOT','var'), NLSTEP_ROOT = getenv('NLSTEP_ROOT'); end
if isempty(NLSTEP_ROOT), error('set NLSTEP_ROOT (the prepared NLstep tree)'); end
if ~exist('OUT_DIR','var'),     OUT_DIR = fullfile(pwd,'out'); end
DRV = struct();
DRV.exampleDir = fullfile(NLSTEP_ROOT,'EXAMPLES','03_bladeCasingRubbing');
DRV.outDir = OUT_DIR;
DRV.startDir = pwd;
if ~exist(DRV.outDir,'dir'), mkdir(DRV.outDir); end

% Headless plotting: the example script makes three figures; keep them
% invisible (gnuplot toolkit, no display needed).
set(0,'defaultfigurevisible','off');

%% 1) Run NLstep's example script as is, timing the whole script
cd(DRV.exampleDir);
DRV.wholeTimer = tic;      % timer id survives the script's clearvars (global)
DRV.wholeCpu0 = cputime;
source('bladeCasingRubbing.m');   % <-- NLstep's own script, PLAUSIBLE set-up
global DRV                         % re-link after the script's clearvars
DRV.tWholeScript_s = toc(DRV.wholeTimer);
DRV.cpuWholeScript_s = cputime - DRV.wholeCpu0;
close all;
fprintf('DRIVER: whole example script wall time = %.2f s (cpu %.2f s)\n', ...
    DRV.tWholeScript_s, DRV.cpuWholeScript_s);

%% 2) Re-run the integration alone, same inputs, with tic/toc around it
% (sim_contact3D's own stopwatch, printed as 'Total elapsed time', starts
% immediately before the time loop; this tic/toc also covers the cheap
% evaluation of the imposed gap/velocity functions on the time grid.)
tIntTimer = tic; cpu0 = cputime;
[Q2,U2,LAM2,CSTATE,Solinfo] = sim_contact3D(t_s,q0,u0,bladeROM);
DRV.tIntegration_s = toc(tIntTimer);
DRV.cpuIntegration_s = cputime - cpu0;
fprintf('DRIVER: integration alone (sim_contact3D call) wall time = %.2f s (cpu %.2f s)\n', ...
    DRV.tIntegration_s, DRV.cpuIntegration_s);
fprintf('DRIVER: max |Q2-Q| = %g, max |LAM2-LAM| = %g (rerun vs example run)\n', ...
    max(abs(Q2(:)-Q(:))), max(abs(LAM2(:)-LAM(:))));

cd(DRV.startDir);
od = DRV.outDir;

%% 3) Exports
nt = numel(t_s);
nb = bladeROM.nb; iN = 1:3:nb; iT1 = iN+1; iT2 = iN+2;

% Response coordinate: row of T for FE dof (node 1353, direction 2 = y)
isensChk = getIndex2NodalDOF(bladeFEmodel,1353,2);
fprintf('DRIVER: response dof index isens=%d -> DOFmap row [%d %d %d]\n', ...
    isensChk, bladeFEmodel.DOFmap(isensChk,:));
qR = bladeROM.Tresp*Q;               % exactly the example's qR (mm)

fid = fopen(fullfile(od,'response.csv'),'w');
fprintf(fid,'t_s,u_1353_dir2_mm\n');
fprintf(fid,'%.12e,%.12e\n',[t_s(:).'; qR(:).']);
fclose(fid);

% Contact states (CSTATE: 0 separated, 1 stick, 2 slip) and forces
nContact = sum(CSTATE>0,1); nStick = sum(CSTATE==1,1); nSlip = sum(CSTATE==2,1);
lamN = LAM(iN,:); lamT1 = LAM(iT1,:); lamT2 = LAM(iT2,:);
% Total contact force on the blade in global axes (lambda acts on the
% blade along the local axes e_n, e_t1, e_t2, cf. K_bb q_b + K_bi q_i - lambda = 0)
Fg = zeros(3,nt);
Rb = R(1:nb,1:nb);                   % local->global for boundary triplets
for j=1:nc
    Rj = Rb(3*j-2:3*j,3*j-2:3*j);
    Fg = Fg + Rj*LAM(3*j-2:3*j,:);
end
fid = fopen(fullfile(od,'contact_states.csv'),'w');
fprintf(fid,['t_s,n_contact,n_stick,n_slip,sum_lambda_n_N,sum_lambda_t1_N,' ...
    'sum_lambda_t2_N,Fx_global_N,Fy_global_N,Fz_global_N,JOR_iterations,JOR_converged\n']);
fprintf(fid,'%.12e,%d,%d,%d,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%d,%d\n', ...
    [t_s(:).'; nContact; nStick; nSlip; sum(lamN,1); sum(lamT1,1); ...
     sum(lamT2,1); Fg; Solinfo.NIT; Solinfo.IEx]);
fclose(fid);

% Per-node contact state matrix (columns = contact nodes in NLstep order)
fid = fopen(fullfile(od,'contact_state_per_node.csv'),'w');
fprintf(fid,'t_s'); fprintf(fid,',node%d',nodeSet_contact); fprintf(fid,'\n');
fprintf(fid,['%.12e' repmat(',%d',1,nc) '\n'],[t_s(:).'; CSTATE]);
fclose(fid);

% Per-node normal contact force
fid = fopen(fullfile(od,'lambda_n_per_node.csv'),'w');
fprintf(fid,'t_s'); fprintf(fid,',node%d_N',nodeSet_contact); fprintf(fid,'\n');
fprintf(fid,['%.12e' repmat(',%.9e',1,nc) '\n'],[t_s(:).'; lamN]);
fclose(fid);

% Gap history of every contact node (normal gap g = q_b,n + g_imp) and the
% details for the first node (188)
gimpAll = zeros(nc,nt); gamimpAll = zeros(nb,nt);
for j=1:nc
    gimpAll(j,:) = bladeROM.nonlinear_elements{j}.imposedGap(t_s);
    gamimpAll(3*j-2:3*j,:) = bladeROM.nonlinear_elements{j}.imposedGapVelocity(t_s);
end
gapAll = Q(iN,:) + gimpAll;
fid = fopen(fullfile(od,'gap_per_node.csv'),'w');
fprintf(fid,'t_s'); fprintf(fid,',g_node%d_mm',nodeSet_contact); fprintf(fid,'\n');
fprintf(fid,['%.12e' repmat(',%.9e',1,nc) '\n'],[t_s(:).'; gapAll]);
fclose(fid);
j = 1;
gam = U2(1:nb,:) + gamimpAll;         % gap velocity gamma_k = u_b,k-1/2 + gamma_imp(t_k)
fid = fopen(fullfile(od,sprintf('gap_node%d.csv',nodeSet_contact(j))),'w');
fprintf(fid,['t_s,g_imp_mm,qb_n_mm,qb_t1_mm,qb_t2_mm,g_mm,lambda_n_N,' ...
    'lambda_t1_N,lambda_t2_N,gamma_n_mm_s,gamma_t1_mm_s,gamma_t2_mm_s,state\n']);
fprintf(fid,'%.12e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%.9e,%d\n', ...
    [t_s(:).'; gimpAll(j,:); Q(3*j-2:3*j,:); gapAll(j,:); LAM(3*j-2:3*j,:); ...
     gam(3*j-2:3*j,:); CSTATE(j,:)]);
fclose(fid);

% ROM frequencies and damping as applied
Dii = diag(bladeROM.D(nb+1:end,nb+1:end));
Kii = bladeROM.K(nb+1:end,nb+1:end);
Kcond = Kii - bladeROM.K(nb+1:end,1:nb)*(bladeROM.K(1:nb,1:nb)\bladeROM.K(1:nb,nb+1:end));
fid = fopen(fullfile(od,'rom_frequencies.csv'),'w');
fprintf(fid,['mode,f_Hz,omega_rad_s,damping_ratio,D_ii_1_per_s,' ...
    'sqrt_diag_Kcond_Hz\n']);
fprintf(fid,'%d,%.9f,%.9f,%.6g,%.9e,%.9f\n',[1:nm; om(:).'/2/pi; om(:).'; ...
    Dii(:).'./(2*om(:).'); Dii(:).'; sqrt(diag(Kcond)).'/2/pi]);
fclose(fid);

%% 4) Checks on the sliding sign (slipping instants, all nodes)
isSlip = (CSTATE==2);
gT2 = gam(iT2,:); lT2 = lamT2; gT1 = gam(iT1,:); lT1 = lamT1;
dotp = (gT1.*lT1 + gT2.*lT2);        % friction force . slip velocity
nrm = sqrt(gT1.^2+gT2.^2).*sqrt(lT1.^2+lT2.^2);
cosang = dotp(isSlip)./nrm(isSlip);
S.nSlipSamples = nnz(isSlip);
S.fracLamT2pos = mean(lT2(isSlip)>0);
S.fracGamT2neg = mean(gT2(isSlip)<0);
S.cosAngle_min = min(cosang); S.cosAngle_max = max(cosang);
S.mean_gamma_t2_slip = mean(gT2(isSlip));
S.mean_gamma_t1_slip = mean(gT1(isSlip));
S.mean_lam_t2_slip = mean(lT2(isSlip));
S.mean_lam_t1_slip = mean(lT1(isSlip));
S.mu_ratio_slip_max = max(sqrt(lT1(isSlip).^2+lT2(isSlip).^2)./lamN(isSlip));

%% 5) Steady-state statistics over the last 5 revolutions
Trev = timePerRevolution_s;
nPerRev = numberOfTimeStepsPerRevolution;
idxSS = (nt-5*nPerRev):nt;           % t in [45 Trev, 50 Trev], 5001 samples
x = qR(idxSS);
SS.mean = mean(x); SS.min = min(x); SS.max = max(x); SS.rms = sqrt(mean(x.^2));
SS.std = std(x,1);
xf = qR((nt-5*nPerRev):(nt-1));      % exactly 5 revolutions, 5000 samples
xf = xf - mean(xf);
N = numel(xf); dt = t_s(2)-t_s(1);
X = fft(xf); A = 2*abs(X(1:N/2+1))/N; f = (0:N/2)/(N*dt);
[~,ipk] = max(A(2:end)); ipk = ipk+1;
[As,is] = sort(A,'descend');
SS.df_Hz = 1/(N*dt); SS.fpeak_Hz = f(ipk); SS.Apeak_mm = A(ipk);
SS.fpeak_over_rev = f(ipk)*Trev;
% Zero-padded (x16, Hann) refinement of the peak
Np = 16*N; w = 0.5-0.5*cos(2*pi*(0:N-1)/N);
Xp = fft(xf.*w, Np); Ap = abs(Xp(1:Np/2+1)); fp = (0:Np/2)/(Np*dt);
[~,ip2] = max(Ap(2:end)); SS.fpeak_refined_Hz = fp(ip2+1);
fid = fopen(fullfile(od,'spectrum_last5rev.csv'),'w');
fprintf(fid,'f_Hz,amplitude_mm\n'); fprintf(fid,'%.9f,%.9e\n',[f; A]); fclose(fid);

%% 6) Summary
fid = fopen(fullfile(od,'summary.txt'),'w');
for ff = {1, fid}
    o = ff{1};
    fprintf(o,'Octave %s\n', version);
    fprintf(o,'n ROM = %d (nb = %d, nm = %d); nt = %d; dt = %.9e s; Trev = %.9e s\n', ...
        bladeROM.n, nb, nm, nt, dt, Trev);
    fprintf(o,'Omega = %g rad/s, mu = %g, g_m = %g mm, CONFIG = %s\n', ...
        Omrot_rad_s, mu, gmean_mm, CONFIG);
    fprintf(o,'response dof: FE index %d = node %d dir %d\n', isensChk, ...
        bladeFEmodel.DOFmap(isensChk,2:3));
    fprintf(o,'first 10 free-interface frequencies used (Hz):'); fprintf(o,' %.4f',om(1:10)/2/pi); fprintf(o,'\n');
    fprintf(o,'damping ratio applied (check) min/max = %.6g / %.6g\n', ...
        min(Dii(:)./(2*om(:))), max(Dii(:)./(2*om(:))));
    fprintf(o,'timings: whole example script %.2f s wall (%.2f s cpu); integration alone %.2f s wall (%.2f s cpu)\n', ...
        DRV.tWholeScript_s, DRV.cpuWholeScript_s, DRV.tIntegration_s, DRV.cpuIntegration_s);
    fprintf(o,'rerun identical: max|dQ| = %g, max|dLAM| = %g\n', max(abs(Q2(:)-Q(:))), max(abs(LAM2(:)-LAM(:))));
    fprintf(o,'JOR: mean iterations %.2f, max %d, non-converged steps %d\n', ...
        mean(Solinfo.NIT), max(Solinfo.NIT), sum(Solinfo.IEx==0));
    fprintf(o,'steps with >=1 contact: %d of %d; max contacts %d; max slip %d; max stick %d\n', ...
        nnz(nContact), nt, max(nContact), max(nSlip), max(nStick));
    fprintf(o,'max total normal force %.6g N; max per-node lambda_n %.6g N\n', max(sum(lamN,1)), max(lamN(:)));
    fprintf(o,'min gap over nodes/time %.6g mm\n', min(gapAll(:)));
    fprintf(o,'slip sign check (%d slipping samples): frac lambda_t2>0 = %.4f, frac gamma_t2<0 = %.4f, cos(angle(lam_T,gamma_T)) in [%.6f, %.6f]\n', ...
        S.nSlipSamples, S.fracLamT2pos, S.fracGamT2neg, S.cosAngle_min, S.cosAngle_max);
    fprintf(o,'  mean gamma_t1/t2 during slip = %.6g / %.6g mm/s; mean lambda_t1/t2 = %.6g / %.6g N; max |lam_T|/lam_N = %.6g\n', ...
        S.mean_gamma_t1_slip, S.mean_gamma_t2_slip, S.mean_lam_t1_slip, S.mean_lam_t2_slip, S.mu_ratio_slip_max);
    fprintf(o,'last 5 revolutions (t in [45,50] Trev, %d samples): mean %.6e, min %.6e, max %.6e, rms %.6e, std %.6e mm\n', ...
        numel(x), SS.mean, SS.min, SS.max, SS.rms, SS.std);
    fprintf(o,'FFT (5000 samples, exactly 5 rev, mean removed): df = %.4f Hz; peak %.4f Hz (= %.3f x rev. freq., amplitude %.6e mm); Hann x16 zero-pad peak %.4f Hz\n', ...
        SS.df_Hz, SS.fpeak_Hz, SS.fpeak_over_rev, SS.Apeak_mm, SS.fpeak_refined_Hz);
    fprintf(o,'top spectral lines (Hz: mm):'); 
    for ii=1:6, fprintf(o,' %.2f: %.3e;', f(is(ii)), As(ii)); end
    fprintf(o,'\n');
end
fclose(fid);
save('-v7', fullfile(od,'results_small.mat'), 't_s','qR','CSTATE','LAM','om','Dii','SS','S');
