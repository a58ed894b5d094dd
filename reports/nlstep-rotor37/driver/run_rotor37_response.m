%========================================================================
% run_rotor37_response.m  --  short Octave driver (written for the rsi
% project, not part of NLstep/NLvib).
%
% Runs NLstep's example EXAMPLES/03_bladeCasingRubbing/bladeCasingRubbing.m
% as it stands in NLSTEP_ROOT (setup_and_run.sh may have set its friction
% coefficient, revolutions and steps a revolution) and writes only
%   OUT_FILE: t_s,u_1353_2_mm,sum_lambda_n_N,steps_per_rev,mu
% (the response qR = Tresp*Q of the example and the total normal force).
% One integration, no rerun (run_rotor37_plausible.m is the full driver).
%
% Usage:
%   octave-cli -q --eval "NLSTEP_ROOT='WORK/NLstep'; OUT_FILE='WORK/out/response_short.csv'; \
%                         run('DRIVER_DIR/run_rotor37_response.m')"
%========================================================================
global DRV
if ~exist('NLSTEP_ROOT','var'), NLSTEP_ROOT = getenv('NLSTEP_ROOT'); end
if isempty(NLSTEP_ROOT), error('set NLSTEP_ROOT (the prepared NLstep tree)'); end
if ~exist('OUT_FILE','var'), OUT_FILE = fullfile(pwd,'response_short.csv'); end
DRV = struct('out', OUT_FILE, 'startDir', pwd);
set(0,'defaultfigurevisible','off');
cd(fullfile(NLSTEP_ROOT,'EXAMPLES','03_bladeCasingRubbing'));
DRV.timer = tic;
source('bladeCasingRubbing.m');      % <-- NLstep's own script
global DRV                            % re-link after the script's clearvars
close all;
cd(DRV.startDir);
qR = bladeROM.Tresp*Q;
lamN = LAM(1:3:bladeROM.nb,:);
fid = fopen(DRV.out,'w');
fprintf(fid,'t_s,u_1353_2_mm,sum_lambda_n_N,steps_per_rev,mu\n');
nt = numel(t_s);
fprintf(fid,'%.12e,%.12e,%.9e,%d,%g\n',[t_s(:).'; qR(:).'; sum(lamN,1); ...
    numberOfTimeStepsPerRevolution*ones(1,nt); mu*ones(1,nt)]);
fclose(fid);
fprintf('DRIVER: mu = %g, %d steps/rev, %d revolutions, %.1f s for the whole script; wrote %s\n', ...
    mu, numberOfTimeStepsPerRevolution, numberOfRevolutions, toc(DRV.timer), DRV.out);
